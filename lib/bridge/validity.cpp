#include "bridge/validity.hpp"

#include <cmath>
#include <numbers>

#include "core/input_error.hpp"

namespace demscale::bridge {

std::vector<ValidityWarning> check_validity(double vhat, ContactAngle theta, const MikamiCoefficients& k,
                                            const ValidityRange& range) {
    std::vector<ValidityWarning> out;
    const std::string v = format_number(vhat);
    if (vhat < range.vhat_min)
        out.push_back({"vhat_below_range", "V^ = " + v + " is below the regression's range [" +
                                               format_number(range.vhat_min) + ", " +
                                               format_number(range.vhat_max) + "]"});
    if (vhat > range.vhat_max)
        out.push_back({"vhat_above_range", "V^ = " + v + " is above the regression's range [" +
                                               format_number(range.vhat_min) + ", " +
                                               format_number(range.vhat_max) + "]"});
    if (theta.degrees() > range.theta_max_deg)
        out.push_back({"theta_above_range", "contact angle " + format_number(theta.degrees()) +
                                                " deg is above the regression's range (<= " +
                                                format_number(range.theta_max_deg) + " deg)"});
    if (theta.radians() > 0.0 && vhat < 0.06)
        out.push_back({"theta_trend_unphysical",
                       "at V^ < 0.06 the fit's theta^2 term makes the force grow with theta (the exact force falls)"});
    if (auto h0 = negative_onset_hhat(k))
        out.push_back({"negative_before_rupture",
                       "the fit turns negative at h^ = " + format_number(*h0) + " < h^_rupture = " +
                           format_number(k.hhat_rupture) + "; the force is clamped to 0 there"});
    const double bound_over_pi_r_gamma =
        (k.geometry == BridgeGeometry::sphere_sphere ? 2.0 : 4.0) * std::cos(theta.radians());
    const double contact = f_over_pi_r_gamma(k, mikami_fhat(k, 0.0));
    if (contact > bound_over_pi_r_gamma)
        out.push_back({"above_physical_bound",
                       "F(contact)/(pi R gamma) = " + format_short(contact, 4) + " exceeds the physical bound " +
                           format_short(bound_over_pi_r_gamma, 4) + " (" + std::string(to_string(k.geometry)) +
                           ", small-volume limit)"});
    return out;
}

std::optional<ValidityWarning> clamped_at(const MikamiCoefficients& k, double hhat) {
    if (!evaluate_mikami(k, hhat).clamped) return std::nullopt;
    return ValidityWarning{"clamped", "the fit is negative here (exp(A h^ + B) + C < 0 before its rupture distance); printed as 0"};
}

}  // namespace demscale::bridge
