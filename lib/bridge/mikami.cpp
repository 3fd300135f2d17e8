#include "bridge/mikami.hpp"

#include <numbers>
#include <stdexcept>

#include "core/input_error.hpp"

namespace demscale::bridge {

double rupture_hhat(double vhat, ContactAngle theta, RuptureLaw law) {
    require_positive(vhat, "vhat");
    const double t = theta.radians();
    switch (law) {
        case RuptureLaw::mikami1998:  // Mikami et al. 1998 (via docs/model.md §1)
            return (0.62 * t + 0.99) * std::pow(vhat, 0.34);
        case RuptureLaw::lian1993:  // Lian, Thornton & Adams 1993
            return (1.0 + 0.5 * t) * std::cbrt(vhat);
        case RuptureLaw::willett2000:  // Willett et al. 2000, Eq. 15
            return (1.0 + 0.5 * t) * (std::cbrt(vhat) + 0.1 * std::pow(vhat, 2.0 / 3.0));
    }
    return 0.0;
}

MikamiCoefficients mikami_coefficients(double vhat, ContactAngle theta, const MikamiOptions& options,
                                       BridgeGeometry geometry) {
    require_positive(vhat, "vhat");
    const double lnv = std::log(vhat);
    const double t2 = theta.radians() * theta.radians();
    MikamiCoefficients k;
    k.variant = options.variant;
    k.geometry = geometry;
    if (geometry == BridgeGeometry::sphere_sphere) {
        k.a = -1.1 * std::pow(vhat, -0.53);                           // Yun & Park 2017 Eq. 6
        k.b = (-0.34 * lnv - 0.96) * t2 - 0.019 * lnv + 0.48;         // Eq. 7
        const double c_slope = options.variant == MikamiVariant::mikami1998 ? 0.0042 : 0.042;
        k.c = c_slope * lnv + 0.078;                                  // Eq. 8 (0.042 printed)
        k.hhat_rupture = rupture_hhat(vhat, theta, options.rupture);
    } else {
        // Mikami 1998 sphere–wall fit (docs/model.md §1; coefficients from a secondary source).
        k.a = -1.9 * std::pow(vhat, -0.51);
        k.b = (-0.016 * lnv - 0.76) * t2 - 0.12 * lnv + 1.2;
        k.c = 0.013 * lnv + 0.18;
        k.hhat_rupture = (0.22 * theta.radians() + 0.95) * std::pow(vhat, 0.32);
    }
    // Eq. 1 as printed uses 2πRγ; Mikami's coefficients imply πRγ (docs/model.md §2).
    k.force_scale = options.variant == MikamiVariant::mikami1998 ? std::numbers::pi : 2.0 * std::numbers::pi;
    return k;
}

MikamiEvaluation evaluate_mikami(const MikamiCoefficients& k, double hhat) {
    require_finite(hhat, "hhat");
    MikamiEvaluation e;
    if (hhat > k.hhat_rupture) return e;
    e.bridge_exists = true;
    e.raw = std::exp(k.a * std::max(hhat, 0.0) + k.b) + k.c;
    e.clamped = e.raw < 0.0;
    e.fhat = e.clamped ? 0.0 : e.raw;
    return e;
}

std::optional<double> negative_onset_hhat(const MikamiCoefficients& k) {
    if (k.c >= 0.0) return std::nullopt;
    // exp(Aĥ + B) = −C  ⇒  ĥ = (ln(−C) − B)/A
    const double h0 = (std::log(-k.c) - k.b) / k.a;
    if (h0 < k.hhat_rupture) return std::max(h0, 0.0);
    return std::nullopt;
}

double mikami_work_to_rupture(const MikamiCoefficients& k, double hhat) {
    if (!(hhat < k.hhat_rupture)) return 0.0;
    const double overlap_part = hhat < 0.0 ? mikami_fhat(k, 0.0) * -hhat : 0.0;
    // F̂ > 0 on one interval of [0, ĥ_c]: exp(Aĥ+B) is monotone, so it crosses −C at most once.
    double lo = std::max(hhat, 0.0), hi = k.hhat_rupture;
    if (k.c < 0.0) {
        const double threshold = std::log(-k.c) - k.b;  // F̂ > 0 ⇔ Aĥ > threshold
        if (k.a == 0.0) {
            if (!(0.0 > threshold)) return overlap_part;
        } else if (k.a < 0.0) {
            hi = std::min(hi, threshold / k.a);
        } else {
            lo = std::max(lo, threshold / k.a);
        }
    }
    if (!(hi > lo)) return overlap_part;
    const auto primitive = [&](double h) {
        return k.a == 0.0 ? (std::exp(k.b) + k.c) * h : std::exp(k.a * h + k.b) / k.a + k.c * h;
    };
    return overlap_part + primitive(hi) - primitive(lo);
}

double bridge_force_newton(const MikamiCoefficients& k, double fhat, double radius_m, double gamma_n_per_m) {
    const double f = k.force_scale * radius_m * gamma_n_per_m * fhat;
    if (!std::isfinite(f))
        throw std::overflow_error("bridge force overflows: R = " + format_number(radius_m) +
                                  " m, gamma = " + format_number(gamma_n_per_m) + " N/m");
    return f;
}

}  // namespace demscale::bridge
