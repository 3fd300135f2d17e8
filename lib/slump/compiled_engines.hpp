// The slump engines that are compiled: one line each, the one list (as LIGGGHTS keeps its compiled
// combinations in one whitelist). Every engine has Mindlin tangential contact; a line names the
// normal law (a registered part: dem/law_parts.hpp), the cohesion law, the rolling law and whether
// the energy ledger books (slump --energy). A scene whose choice is on no line is refused, exit 2, naming the choice and this
// list. Each line is one instantiation of the protocol's engine, compiled in the
// slump_engines_*.cpp of its cohesion law (compile cost: docs/development.md). Ai's rolling law
// (epsd, every shipped scene's) keeps an engine of its own: run-time choice costs it 2.2 % more
// instructions dry (docs/performance.md); epsd2 and constant torque share one (dem::RollingChosen),
// without the ledger.
#pragma once

#include <span>
#include <string>

#include "dem/law_parts.hpp"
#include "slump/slump_scene.hpp"

namespace demscale::slump {

// liquid_bridge: one R for every bridge (one radius); liquid_bridge_pairs: each pair's harmonic-mean R
// (a size distribution, or a start state of unequal spheres).
enum class CohesionChoice { none, liquid_bridge, liquid_bridge_pairs, sjkr };
// none: free rolling; epsd: Ai's spring and dashpot; run_time: epsd2 or constant torque, as the scene says.
enum class RollingEngine { none, epsd, run_time };

struct EngineLine {
    const dem::LawPart* normal;  // a part of dem::normal_laws
    CohesionChoice cohesion;
    RollingEngine rolling;
    bool ledger;  // the energy ledger books every loss
    // The normal laws by their choice values (never null): a constant expression under
    // AddressSanitizer too, where GCC folds no comparison of an object's address.
    friend constexpr bool operator==(const EngineLine& a, const EngineLine& b) {
        return a.normal->choice == b.normal->choice && a.cohesion == b.cohesion && a.rolling == b.rolling && a.ledger == b.ledger;
    }
};

inline constexpr EngineLine compiled_engines[] = {
    // normal            cohesion                      rolling                  ledger
    {&dem::hertz_part, CohesionChoice::none,          RollingEngine::epsd,     false},  // the dry control of every study
    {&dem::hertz_part, CohesionChoice::none,          RollingEngine::none,     false},
    {&dem::hertz_part, CohesionChoice::none,          RollingEngine::run_time, false},
    {&dem::hertz_part, CohesionChoice::none,          RollingEngine::epsd,     true},
    {&dem::hertz_part, CohesionChoice::none,          RollingEngine::none,     true},
    {&dem::hertz_part, CohesionChoice::liquid_bridge, RollingEngine::epsd,     false},  // the wet reference scene
    {&dem::hertz_part, CohesionChoice::liquid_bridge, RollingEngine::none,     false},
    {&dem::hertz_part, CohesionChoice::liquid_bridge, RollingEngine::run_time, false},
    {&dem::hertz_part, CohesionChoice::liquid_bridge, RollingEngine::epsd,     true},
    {&dem::hertz_part, CohesionChoice::liquid_bridge, RollingEngine::none,     true},
    {&dem::hertz_part, CohesionChoice::liquid_bridge_pairs, RollingEngine::epsd, false},  // wet size distributions
    {&dem::hertz_part, CohesionChoice::liquid_bridge_pairs, RollingEngine::epsd, true},
    {&dem::hertz_part, CohesionChoice::sjkr,          RollingEngine::epsd,     false},
    {&dem::hertz_part, CohesionChoice::sjkr,          RollingEngine::none,     false},
    {&dem::hertz_part, CohesionChoice::sjkr,          RollingEngine::run_time, false},
    {&dem::hertz_part, CohesionChoice::sjkr,          RollingEngine::epsd,     true},
    {&dem::hertz_part, CohesionChoice::sjkr,          RollingEngine::none,     true},
    {&dem::hooke_part, CohesionChoice::none,          RollingEngine::epsd,     false},  // a linear-spring dry scene
};

// The cohesion law a scene chooses: a liquid bridge when wet (each pair's R when its spheres, or
// those of the start state, have unequal radii), SJKR adhesion when it gives a cohesion energy
// density, none otherwise.
CohesionChoice cohesion_choice(const SlumpScene& s, bool unequal_start = false);

// The rolling engine a scene chooses.
RollingEngine rolling_engine(const SlumpScene& s);

// The registered normal law the scene chooses (contact.normal_law); std::logic_error if none is.
const dem::LawPart* normal_choice(const SlumpScene& s);

// "Hertz normal contact, liquid bridge, epsd rolling, energy ledger": a line for people (with the scene: its run-time rolling law).
std::string engine_name(const EngineLine& line, const SlumpScene* s = nullptr);

// "hertz+mindlin+liquid_bridge(mikami1998)": the chosen laws that act (dem::chosen_laws), the
// bridge's curve source in brackets; the bench's rows.
std::string laws_label(const SlumpScene& s);

// The line that runs this scene (with the ledger or not; unequal_start: from a start state of
// unequal spheres); an InputError naming the scene's choice and every line of `list` when none matches.
EngineLine listed_engine(const SlumpScene& s, bool ledger, bool unequal_start = false, std::span<const EngineLine> list = compiled_engines);

}  // namespace demscale::slump
