#include "slump/compiled_engines.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/input_error.hpp"
#include "dem/bridge_law.hpp"

namespace demscale::slump {

CohesionChoice cohesion_choice(const SlumpScene& s, bool unequal_start) {
    if (s.wet) return s.sizes.monodisperse() && !unequal_start ? CohesionChoice::liquid_bridge : CohesionChoice::liquid_bridge_pairs;
    return dem::sjkr_part.active(s) ? CohesionChoice::sjkr : CohesionChoice::none;
}

const dem::LawPart* normal_choice(const SlumpScene& s) {
    return [&]<class... Law>(std::tuple<Law...>*) {
        const dem::LawPart* chosen = nullptr;
        ((chosen = chosen == nullptr && Law::part->active(s) ? Law::part : chosen), ...);
        if (chosen == nullptr) throw std::logic_error("no registered normal law is \"" + std::string(s.normal_law) + "\"");
        return chosen;
    }(static_cast<dem::normal_laws*>(nullptr));
}

RollingEngine rolling_engine(const SlumpScene& s) {
    if (!s.rolling_resistance) return RollingEngine::none;
    return s.rolling_model == RollingModel::epsd ? RollingEngine::epsd : RollingEngine::run_time;
}

std::string engine_name(const EngineLine& line, const SlumpScene* s) {
    std::string name = std::string(line.normal->name) + ", ";
    name += line.cohesion == CohesionChoice::liquid_bridge         ? "liquid bridge"
            : line.cohesion == CohesionChoice::liquid_bridge_pairs ? "liquid bridge of each pair's radius"
            : line.cohesion == CohesionChoice::sjkr                ? "SJKR adhesion"
                                                                   : "no cohesion";
    if (line.rolling == RollingEngine::none) name += ", free rolling";
    else if (line.rolling == RollingEngine::epsd) name += ", epsd rolling";
    else if (s) name += s->rolling_model == RollingModel::epsd2 ? ", epsd2 rolling" : ", constant_torque rolling";
    else name += ", epsd2 or constant_torque rolling";
    return name + (line.ledger ? ", energy ledger" : "");
}

std::string laws_label(const SlumpScene& s) {
    std::string label;
    for (const auto law : dem::chosen_laws(s)) label += (label.empty() ? "" : "+") + std::string(law);
    return s.wet ? label + "(" + std::string(dem::particle_curve_source(s).value) + ")" : label;
}

EngineLine listed_engine(const SlumpScene& s, bool ledger, bool unequal_start, std::span<const EngineLine> list) {
    const EngineLine wanted{normal_choice(s), cohesion_choice(s, unequal_start), rolling_engine(s), ledger};
    if (std::find(list.begin(), list.end(), wanted) != list.end()) return wanted;
    std::string lines;
    for (const auto& line : list) lines += (lines.empty() ? "" : "; ") + engine_name(line);
    throw InputError(s.source.empty() ? "scene" : s.source, "the contact laws " + engine_name(wanted, &s),
                     "one of the compiled engines (lib/slump/compiled_engines.hpp): " + lines);
}

}  // namespace demscale::slump
