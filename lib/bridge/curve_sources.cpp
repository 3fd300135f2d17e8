#include "bridge/curve_sources.hpp"

#include <stdexcept>

#include "bridge/closed_forms.hpp"
#include "bridge/mikami.hpp"
#include "bridge/validity.hpp"

namespace demscale::bridge {

namespace {

constexpr ValidityRange mikami_range;

// A fit with the scene's own options: its printed form also sets the wall fit's force scale.
BridgeCurve mikami_fit(double vhat, ContactAngle theta, BridgeGeometry geometry, const MikamiOptions& fit) {
    return mikami_coefficients(vhat, theta, fit, geometry);
}

const CurveSourceEntry entries[] = {
    {"mikami1998", CurveSource::fit, MikamiVariant::mikami1998,
     "Mikami et al.'s (1998) regression (to a wall: their sphere-wall fit)", true, true, mikami_range.vhat_min, mikami_range.vhat_max,
     "the Mikami fit's range",
     mikami_fit,
     "cohesion easo/capillary/viscous", ""},
    {"yun-park-2017", CurveSource::fit, MikamiVariant::yun_park_2017, "Mikami's regression as Yun & Park (2017) print it (Eqs. 1-8)",
     true, false, mikami_range.vhat_min, mikami_range.vhat_max, "the Mikami fit's range",
     mikami_fit,
     "", ""},
    {"table", CurveSource::exact, MikamiVariant::mikami1998,
     "the exact Young-Laplace bridge at the scene's V^ and theta (table)", true, true, mikami_range.vhat_min, mikami_range.vhat_max,
     "the Mikami fit's range (where the exact bridge is checked against it)",
     [](double vhat, ContactAngle theta, BridgeGeometry g, const MikamiOptions&) { return BridgeCurve::exact(vhat, theta, g); }, "",
     "exact"},
    // Willett et al. (2000), Langmuir 16:9396, the full fit (appendix) with their rupture (Eq. 15):
    // evaluated for V̂ in [1e-6, 1], where its polynomials stay finite (docs/bridge-models.md).
    {"willett", CurveSource::willett, MikamiVariant::mikami1998,
     "Willett et al. (2000) full fit, rupture Eq. 15, tabulated", true, false, 1e-6, 1.0, "the range where Willett et al.'s fit stays finite",
     [](double vhat, ContactAngle theta, BridgeGeometry, const MikamiOptions&) {
         return BridgeCurve::tabulated([&](double hhat) { return willett_full_fhat(vhat, theta, hhat); }, willett_rupture_hhat(vhat, theta));
     },
     "", "willett"},
};

}  // namespace

std::span<const CurveSourceEntry> curve_sources() { return entries; }

const CurveSourceEntry& curve_source(CurveSource source, MikamiVariant fit_variant, BridgeGeometry geometry) {
    for (const auto& e : entries)
        if (e.source == source && e.has(geometry) && (source != CurveSource::fit || e.fit_variant == fit_variant)) return e;
    for (const auto& e : entries)  // a fit whose printed form has no wall form: the wall fit
        if (e.source == source && e.has(geometry)) return e;
    throw std::logic_error("no bridge curve source for this choice");
}

const CurveSourceEntry* find_curve_source(std::string_view value, BridgeGeometry geometry) {
    for (const auto& e : entries)
        if (e.value == value && e.has(geometry)) return &e;
    return nullptr;
}

std::string curve_source_values(BridgeGeometry geometry) {
    std::string out;
    for (const auto& e : entries)
        if (e.has(geometry)) out += (out.empty() ? "" : ", ") + std::string(e.value);
    return out;
}

}  // namespace demscale::bridge
