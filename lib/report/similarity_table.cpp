#include "report/similarity_table.hpp"

#include <cmath>
#include <set>

#include "bridge/validity.hpp"
#include "core/input_error.hpp"
#include "core/version.hpp"
#include "similarity/exponent_similarity.hpp"
#include "similarity/stress_similarity.hpp"

namespace demscale::report {

std::string exponent_tag(double k) {
    std::string s = format_number(std::abs(k));
    for (char& ch : s)
        if (ch == '.') ch = 'p';
    return (k < 0 ? "m" : "") + s;
}

std::vector<std::pair<std::string, std::string>> study_metadata(const io::TableConfig& c, const Table1Particles& p) {
    const bool printed = c.bridge.variant == bridge::MikamiVariant::yun_park_2017;
    std::vector<std::pair<std::string, std::string>> m = {
        {"demscale", version},
        {"inputs", c.source},
        {"bridge_variant", std::string(to_string(c.bridge.variant))},
        {"force_law", printed ? "F = 2 pi R gamma (exp(A h^ + B) + C), C = 0.042 ln V^ + 0.078 (Yun & Park 2017 Eqs. 1-8 as printed)"
                              : "F = pi R gamma (exp(A h^ + B) + C), C = 0.0042 ln V^ + 0.078 (Mikami et al. 1998)"},
        {"rupture_law", std::string(to_string(c.bridge.rupture))},
        {"surface_tension_n_per_m", format_number(c.liquid.surface_tension_n_per_m)},
        {"contact_angle_deg", format_number(c.liquid.contact_angle.degrees())},
        {"liquid_density_kg_per_m3", format_number(c.liquid.density_kg_per_m3)},
        {"moisture_content", format_number(c.liquid.moisture_content)},
        {"physical_radius_mm", format_number(c.physical_radius_m * 1e3)},
        {"mass_source", c.mass_source == io::MassSource::density ? "density (m = rho 4/3 pi R^3, Eqs. 9-10)"
                                                                 : "table (masses as printed)"},
        {"solid_density_kg_per_m3", format_short(p.solid_density_kg_per_m3, 6) +
                                        (c.solid_density_kg_per_m3 ? " (given)" : " (least-squares fit to the table masses)")},
    };
    if (p.fit) {
        std::string s = format_short(p.fit->least_squares_kg_per_m3, 6) + " least squares";
        if (p.fit->consistent_min_kg_per_m3)
            s += "; every printed mass rounds correctly for rho in [" + format_short(*p.fit->consistent_min_kg_per_m3, 6) +
                 ", " + format_short(*p.fit->consistent_max_kg_per_m3, 6) + "]";
        else
            s += "; no single density reproduces every printed mass";
        m.emplace_back("density_implied_by_table_kg_per_m3", s);
    }
    return m;
}

io::Table similarity_table(const io::TableConfig& c, const std::vector<double>& exponents) {
    const Table1Particles p = table1_particles(c);
    const double gamma = c.liquid.surface_tension_n_per_m;
    const bridge::MikamiCoefficients k_phys = bridge::mikami_coefficients(p.physical.vhat, c.liquid.contact_angle, c.bridge);
    const double fhat_phys = bridge::mikami_fhat(k_phys, 0.0);
    const double f_phys = bridge::bridge_force_newton(k_phys, fhat_phys, p.physical.radius_m, gamma);
    const double sigma_phys = f_phys / (M_PI * p.physical.radius_m * p.physical.radius_m);

    io::Table t;
    t.title = "Similarity table (Yun & Park 2017, Table 1 and Eqs. 1-12)";
    t.metadata = study_metadata(c, p);
    t.metadata.emplace_back("ratios", "to the physical particle (R = " + format_number(c.physical_radius_m * 1e3) +
                                          " mm, physical gamma): F_k/F_phys and sigma_k/sigma_phys at contact");
    t.columns = {"radius_mm", "sf", "mass_g", "mass_table_g", "mass_table_dev_pct", "particle_volume_mm3",
                 "replaced_count", "v_mm3", "vhat", "a", "b", "c", "f_over_pi_r_gamma_contact",
                 "f_over_2pi_r_gamma_contact", "fc_contact_n", "hhat_rupture"};
    t.headings = {"particle radius R (mm)", "S_f", "particle mass (g)", "mass in the paper's Table 1 (g)",
                  "difference from the paper's mass (%)", "particle volume (mm³)", "fine particles replaced (S_f³)",
                  "bridge liquid V (mm³)", "V̂ = V/R³", "Mikami A", "Mikami B", "Mikami C", "F/(π R γ) at contact",
                  "F/(2π R γ) at contact", "bridge force at contact, physical γ (N)", "rupture gap ĥ_c (gap/R)"};
    for (double k : exponents) {
        const std::string tag = exponent_tag(k), at = " at k = " + format_short(k);
        for (const char* col : {"gamma_n_per_m_k", "fc_contact_n_k", "sigma_contact_pa_k", "force_ratio_k", "sigma_ratio_k"})
            t.columns.push_back(col + tag);
        for (const std::string& h : {"γ̄" + at + " (N/m)", "bridge force at contact" + at + " (N)", "bridge stress F/(π R²)" + at + " (Pa)",
                                     "F / F physical" + at, "σ / σ physical" + at})
            t.headings.push_back(h);
    }
    t.columns.push_back("validity");
    t.headings.push_back("validity");

    std::set<std::string> notes;
    for (std::size_t i = 0; i < p.rows.size(); ++i) {
        const auto& q = p.rows[i];
        const auto coeff = bridge::mikami_coefficients(q.vhat, c.liquid.contact_angle, c.bridge);
        const double fhat0 = bridge::mikami_fhat(coeff, 0.0);
        std::vector<io::Cell> row = {q.radius_m * 1e3, q.sf, q.mass_kg * 1e3};
        if (const auto& tab = p.tabulated_mass_kg[i]) {
            row.push_back(*tab * 1e3);
            const double rho_mass = p.solid_density_kg_per_m3 * q.volume_m3;
            row.push_back(100.0 * (*tab - rho_mass) / rho_mass);
        } else {
            row.push_back(std::string("-"));
            row.push_back(std::string("-"));
        }
        row.insert(row.end(), {q.volume_m3 * 1e9, q.replaced_count, q.liquid_volume_m3 * 1e9, q.vhat, coeff.a, coeff.b,
                               coeff.c, bridge::f_over_pi_r_gamma(coeff, fhat0), bridge::f_over_2pi_r_gamma(coeff, fhat0),
                               bridge::bridge_force_newton(coeff, fhat0, q.radius_m, gamma), coeff.hhat_rupture});
        for (double k : exponents) {
            const auto s = similarity::stress_similarity(coeff, fhat0, q.radius_m, gamma, q.sf, k);
            row.insert(row.end(), {s.gamma_n_per_m, s.force_n, s.sigma_pa, s.force_n / f_phys, s.sigma_pa / sigma_phys});
        }
        std::string flags;
        for (const auto& w : bridge::check_validity(q.vhat, c.liquid.contact_angle, coeff)) {
            flags += (flags.empty() ? "" : ";") + w.code;
            notes.insert("R = " + format_number(q.radius_m * 1e3) + " mm: " + w.message);
        }
        row.push_back(flags.empty() ? std::string("ok") : flags);
        t.rows.push_back(std::move(row));
    }
    t.notes.assign(notes.begin(), notes.end());

    // The other printed form, side by side, at the physical particle (the paper/physics disagreement).
    bridge::MikamiOptions other = c.bridge;
    other.variant = c.bridge.variant == bridge::MikamiVariant::mikami1998 ? bridge::MikamiVariant::yun_park_2017
                                                                          : bridge::MikamiVariant::mikami1998;
    const auto k_other = bridge::mikami_coefficients(p.physical.vhat, c.liquid.contact_angle, other);
    const double f_other = bridge::bridge_force_newton(k_other, bridge::mikami_fhat(k_other, 0.0), p.physical.radius_m, gamma);
    if (!c.sizes_note.empty()) t.notes.push_back(c.sizes_note);
    t.notes.push_back("variant check at R = " + format_number(c.physical_radius_m * 1e3) + " mm, contact: " +
                      std::string(to_string(c.bridge.variant)) + " F_C = " + format_short(f_phys) + " N, " +
                      std::string(to_string(other.variant)) + " F_C = " + format_short(f_other) + " N (ratio " +
                      format_short(f_other / f_phys) + "); physical bound 2 pi R gamma cos(theta) = " +
                      format_short(2 * M_PI * p.physical.radius_m * gamma * std::cos(c.liquid.contact_angle.radians())) +
                      " N");
    return t;
}

io::Table similarity_groups_table(const std::vector<double>& exponents) {
    io::Table t;
    t.title = "Similarity groups under particle replacement (S_L = S_f, S_rho = 1, gamma = gamma0 S_f^k)";
    t.metadata = {{"reading", "each cell is the exponent e in (coarse/fine) = S_f^e; 0 means the group is kept"}};
    t.columns = {"group", "k_keeping_it"};
    for (double k : exponents) t.columns.push_back("exponent_at_k" + exponent_tag(k));
    std::vector<similarity::ExponentSimilarity> s;
    for (double k : {0.0, 1.0}) s.push_back(similarity::exponent_similarity(k));
    for (double k : exponents) s.push_back(similarity::exponent_similarity(k));
    // Every exponent is linear in k: e(k) = e(0) + (e(1) − e(0)) k, so the keeping k is −e(0)/slope.
    auto keeping = [](double e0, double e1) -> io::Cell {
        if (e1 == e0) return std::string(e0 == 0 ? "any" : "none");
        return -e0 / (e1 - e0);
    };
    auto add = [&](const std::string& name, auto value_of) {
        std::vector<io::Cell> row = {name, keeping(value_of(s[0]), value_of(s[1]))};
        for (std::size_t i = 2; i < s.size(); ++i) row.push_back(value_of(s[i]));
        t.rows.push_back(std::move(row));
    };
    for (std::size_t g = 0; g < s[0].groups.size(); ++g)
        add(s[0].groups[g].name, [g](const similarity::ExponentSimilarity& x) { return x.groups[g].sf_exponent; });
    add("implied time scale S_T = S_f^t: t", [](const similarity::ExponentSimilarity& x) { return x.time_exponent; });
    for (std::size_t h = 0; h < s[0].held.size(); ++h)
        add(s[0].held[h].what + " held; the implied basis demands S_f^e",
            [h](const similarity::ExponentSimilarity& x) { return x.held[h].demanded_exponent; });
    t.notes.push_back("the implied basis: surface tension (rho L^3 T^-2) scaled by S_f^k with S_L = S_f, S_rho = 1 fixes S_T");
    t.notes.push_back("a held parameter whose demanded exponent is not 0 is a broken similarity condition (partial similarity)");
    return t;
}

}  // namespace demscale::report
