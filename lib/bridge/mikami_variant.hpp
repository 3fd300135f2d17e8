// Named choices for the Mikami et al. (1998) liquid-bridge regression: which printed form,
// which rupture law, and which geometry (sphere–sphere or sphere–wall). See docs/model.md §2.
#pragma once

#include <string>
#include <string_view>

namespace demscale::bridge {

// mikami1998:    F = πRγ·F̂, C = 0.0042·ln V̂ + 0.078 — as in public implementations; stays below
//                the physical bound 2πRγ·cos θ (docs/model.md §2). The default.
// yun_park_2017: F = 2πRγ·F̂ (paper Eq. 1), C = 0.042·ln V̂ + 0.078 (paper Eq. 8) — exactly as printed.
enum class MikamiVariant { mikami1998, yun_park_2017 };

// Rupture distance ĥ_c = h_c/R (full gap):
// mikami1998: (0.62θ + 0.99)·V̂^0.34;  lian1993: (1 + θ/2)·V̂^(1/3);
// willett2000 (Eq. 15): (1 + θ/2)·(V̂^(1/3) + 0.1·V̂^(2/3)).
enum class RuptureLaw { mikami1998, lian1993, willett2000 };

enum class BridgeGeometry { sphere_sphere, sphere_wall };

std::string_view to_string(MikamiVariant v);
std::string_view to_string(RuptureLaw r);
std::string_view to_string(BridgeGeometry g);

// Parse the names above; `field` names the input in the error message.
MikamiVariant parse_mikami_variant(std::string_view text, const std::string& field);
RuptureLaw parse_rupture_law(std::string_view text, const std::string& field);

}  // namespace demscale::bridge
