// Export of a slump scene to LIGGGHTS (3.8, Debian's liggghts): the settled particles as a data
// file (atom_style granular), the cone as an STL mesh, and an input deck with the same laws
// (hertz, tangential history, and the scene's rolling law: epsd3 with Ai's 2.25 and no damping for
// demscale's epsd, epsd2, or cdt), parameters, time step, lift and spread, ending
// in a dump of the final pile. A rough floor's grains follow the pile in the data file, in a group
// that is never integrated (held in place). A wet scene's bridges become cohesion
// easo/capillary/viscous (Soulié et al.'s form of Mikami's regression); the deck's header says
// what differs, a bridge curve LIGGGHTS has no equivalent for included.
#pragma once

#include <filesystem>
#include <vector>

#include "dem/particles.hpp"
#include "slump/slump_scene.hpp"

namespace demscale::slump {

// The deck's step counts: the lift (lift height / lift speed / dt), the spread (spread time / dt),
// and with stop_at_rest the steps between two rest checks (a quarter of the rest duration).
struct DeckSteps {
    long lift, spread, rest_check;
};
DeckSteps deck_steps(const SlumpScene& scene);

// The line a deck with stop_at_rest prints when the pile is at rest, before its step number.
inline constexpr const char* liggghts_rest_line = "demscale: at rest at step ";

// Writes in.slump, particles.data and cone.stl into out_dir; returns their paths. The deck ends in
// final.dump: id, type, x, y, z, radius and velocity of the pile's spheres, every digit (%.17g).
// It spreads for the scene's whole spread time, or with stop_at_rest until the pile is at rest by
// demscale's criterion (slump/motion.hpp: at most (1 − q) of the spheres at the rest speed or
// faster, at five checks rest_check steps apart, so over the rest duration), then prints
// liggghts_rest_line and its step.
std::vector<std::filesystem::path> export_liggghts(const slump::SlumpScene& scene, const dem::Particles& settled,
                                                   const std::filesystem::path& out_dir, bool stop_at_rest = false);

}  // namespace demscale::slump
