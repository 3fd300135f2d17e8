// A slump scene as the text its run-cache key hashes: one "name=value" line for every input that
// decides a run's result (%.17g, so each number survives the trip exactly), and back again. The
// key is this text's hash; the text itself is how a run planned here is handed, unchanged, to a
// process elsewhere (a Slurm task, docs/cluster.md).
#pragma once

#include <span>
#include <string>

#include "dem/law_parts.hpp"
#include "slump/slump_scene.hpp"

namespace demscale::slump {

// Part of every text and key: bump it whenever a change to the engine or the protocol changes
// results, so runs cached by older code are not reused.
// 2: history carries the energy ledger; 3: repose flank above the foot; 4: poured fills, quantile
// rest criterion, fill measures and motion at the end; 5: law parameters keyed from their tables;
// 6: scenes of 16 384 spheres or more reorder them along a space-filling curve (dem/spatial_order);
// 7: Hertz–Mindlin with four square roots a contact instead of seven (results move in the last bits);
// 8: every scene reorders its spheres in space, not only large ones (the pair order follows);
// 9: the sort lays its layers along the scene's longest side, not always z (the pair order follows).
// 10: fills cut to the scene's mass (fill_solid_fraction); heights, spreads and profiles from the surface.
// 11: the bridge's normal lubrication takes the finite-volume factor by default (liquid.lubrication).
inline constexpr int cache_format = 11;

// The lines, in a fixed order: the tool's version and cache format, geometry, which laws act, the
// parameters of each part that acts (a part that does not act leaves no trace: a dry run has no
// liquid, so the coarse runs of every k share one text), then the protocol.
std::string scene_text(const SlumpScene& s, std::span<const dem::LawPart> parts = dem::law_parts());

// The scene a text describes (name and source: `source`). Throws InputError naming `source` and
// the line when a line is unknown or malformed, when the text was written by another version or
// cache format, or when the scene read back would not write the same text.
SlumpScene scene_from_text(const std::string& text, const std::string& source,
                           std::span<const dem::LawPart> parts = dem::law_parts());

}  // namespace demscale::slump
