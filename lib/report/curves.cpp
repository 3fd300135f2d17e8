#include "report/curves.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "bridge/mikami.hpp"
#include "core/input_error.hpp"
#include "report/similarity_table.hpp"
#include "report/table1_particles.hpp"
#include "similarity/stress_similarity.hpp"

namespace demscale::report {

std::vector<CurvePoint> compute_curves(const io::TableConfig& c, Figure figure, const std::vector<double>& exponents) {
    const Table1Particles p = table1_particles(c);
    const std::vector<double> ks = figure == Figure::force ? std::vector<double>{0.0} : exponents;
    const auto other = c.bridge.variant == bridge::MikamiVariant::mikami1998 ? bridge::MikamiVariant::yun_park_2017
                                                                             : bridge::MikamiVariant::mikami1998;
    std::vector<CurvePoint> out;
    for (auto variant : {c.bridge.variant, other}) {
        bridge::MikamiOptions options = c.bridge;
        options.variant = variant;
        for (const auto& q : p.rows) {
            const auto coeff = bridge::mikami_coefficients(q.vhat, c.liquid.contact_angle, options);
            for (double k : ks) {
                for (int i = 0; i < c.curve_points; ++i) {
                    const double hhat = c.curve_hhat_max * i / (c.curve_points - 1);
                    const auto e = bridge::evaluate_mikami(coeff, hhat);
                    const auto s = similarity::stress_similarity(coeff, e.fhat, q.radius_m,
                                                                 c.liquid.surface_tension_n_per_m, q.sf, k);
                    out.push_back({variant, q.radius_m, q.sf, k, hhat, bridge::f_over_pi_r_gamma(coeff, e.fhat),
                                   bridge::f_over_2pi_r_gamma(coeff, e.fhat), s.force_n, s.sigma_pa, e.bridge_exists,
                                   e.clamped});
                }
            }
        }
    }
    return out;
}

namespace {
// The exponents the points were computed for, in order of first appearance.
std::vector<double> exponents_of(const std::vector<CurvePoint>& points) {
    std::vector<double> ks;
    for (const auto& q : points)
        if (std::find(ks.begin(), ks.end(), q.exponent) == ks.end()) ks.push_back(q.exponent);
    return ks;
}
}  // namespace

io::Table curves_table(const io::TableConfig& c, Figure figure, const std::vector<CurvePoint>& points) {
    io::Table t;
    t.title = figure == Figure::force ? "Fig. 3: dimensionless capillary force vs dimensionless gap"
                                      : "Fig. 4: bridge stress vs dimensionless gap for each surface-tension exponent";
    t.metadata = study_metadata(c, table1_particles(c));
    auto list = [](const std::vector<double>& xs, double unit) {
        std::string text;
        for (double x : xs) text += (text.empty() ? "" : ", ") + format_number(x / unit);
        return text;
    };
    t.metadata.emplace_back("radii_mm", list(c.radii_m, 1e-3));
    if (figure == Figure::stress) t.metadata.emplace_back("exponents", list(exponents_of(points), 1));
    t.metadata.emplace_back("gap_grid", "hhat from 0 to " + format_number(c.curve_hhat_max) + ", " + std::to_string(c.curve_points) + " points");
    t.metadata.emplace_back("columns",
                            "hhat = full gap / R; f_over_pi_r_gamma = F/(pi R gamma); force_n and sigma_pa use "
                            "gamma = gamma0 S_f^exponent, sigma = F/(pi R^2) (Eq. 11)" +
                                std::string(figure == Figure::force ? "; exponent 0 = physical gamma" : ""));
    t.columns = {"variant", "radius_mm", "sf", "exponent", "hhat", "f_over_pi_r_gamma", "f_over_2pi_r_gamma",
                 "force_n", "sigma_pa", "bridge_exists", "clamped"};
    for (const auto& q : points)
        t.rows.push_back({std::string(to_string(q.variant)), q.radius_m * 1e3, q.sf, q.exponent, q.hhat,
                          q.f_over_pi_r_gamma, q.f_over_2pi_r_gamma, q.force_n, q.sigma_pa,
                          q.bridge_exists ? 1.0 : 0.0, q.clamped ? 1.0 : 0.0});
    return t;
}

std::vector<Collapse> measure_collapse(const std::vector<CurvePoint>& points, Figure figure) {
    // (variant, exponent, ĥ) → values over radii
    std::map<std::tuple<int, double, double>, std::pair<double, double>> range;
    for (const auto& q : points) {
        const double v = figure == Figure::force ? q.f_over_pi_r_gamma : q.sigma_pa;
        auto key = std::make_tuple(static_cast<int>(q.variant), q.exponent, q.hhat);
        auto [it, fresh] = range.try_emplace(key, v, v);
        if (!fresh) it->second = {std::min(it->second.first, v), std::max(it->second.second, v)};
    }
    std::map<std::pair<int, double>, double> worst;
    for (const auto& [key, mm] : range) {
        const double scale = std::max(std::abs(mm.first), std::abs(mm.second));
        const double spread = scale > 0 ? (mm.second - mm.first) / scale : 0.0;
        double& w = worst[{std::get<0>(key), std::get<1>(key)}];
        w = std::max(w, spread);
    }
    std::vector<Collapse> out;
    for (const auto& [key, w] : worst) out.push_back({static_cast<bridge::MikamiVariant>(key.first), key.second, w});
    return out;
}

}  // namespace demscale::report
