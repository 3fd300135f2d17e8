#include "report/scene_table.hpp"

#include "core/input_error.hpp"
#include "dem/bridge_law.hpp"

namespace demscale::report {

io::Table scene_table(const slump::SlumpScene& s, const std::string& label, std::span<const dem::LawPart> parts) {
    io::Table t;
    t.title = "Slump scene (" + label + ")";
    t.columns = {"parameter", "value", "unit"};
    auto add = [&](const std::string& name, double value, const std::string& unit) { t.rows.push_back({name, value, unit}); };
    auto say = [&](const std::string& name, const std::string& value) { t.rows.push_back({name, value, std::string("-")}); };
    t.rows.push_back({"cone bottom / top inner diameter",
                      format_short(s.bottom_diameter_m * 1e3) + " / " + format_short(s.top_diameter_m * 1e3), std::string("mm")});
    add("cone height", s.height_m * 1e3, "mm");
    add("cone lift speed", s.lift_speed_m_per_s, "m/s");
    add(s.sizes.monodisperse() ? "particle radius R (physical, S_f = 1)" : "mass-median particle radius R (physical, S_f = 1)", s.radius_m * 1e3, "mm");
    if (!s.sizes.monodisperse()) {
        say("particle sizes", slump::describe(s.sizes) + "; coarse-grained: every size times S_f");
        say("bridges between unequal spheres", s.wet ? "R* = 2 R1 R2 / (R1 + R2) in force and rupture, V = V^ R*^3 (Willett et al. 2000)" : "none (dry)");
    }
    add("particle density", s.material.density, "kg/m^3");
    add("fill height", s.fill_height_m * 1e3, "mm");
    say("fill", s.fill == slump::FillKind::poured ? "poured in batches, cut to the scene's mass" : "hcp lattice, cut to the scene's mass");
    // The laws the scene chose, each by its part's name (dem/law_parts.hpp).
    std::string laws;
    for (const auto& part : parts)
        if (!part.choice.empty() && part.active(s)) laws += (laws.empty() ? "" : "; ") + std::string(part.name);
    say("contact laws", laws);
    say("rolling resistance", !s.rolling_resistance                                  ? "none"
                              : s.rolling_model == slump::RollingModel::epsd2        ? "epsd2 (k_r = k_t R*^2)"
                              : s.rolling_model == slump::RollingModel::constant_torque ? "constant torque (Ai's model A)"
                                                                                       : "epsd (Ai's model C, with dashpot)");
    // Each curve source's own row (bridge/curve_sources.hpp); a fit also names its rupture law.
    auto named = [](const bridge::CurveSourceEntry& source) { return std::string(source.value) + ": " + std::string(source.label); };
    say("bridge model", !s.wet ? "none (dry)"
                               : named(dem::particle_curve_source(s)) +
                                     (s.particle_curve == bridge::CurveSource::fit ? ", rupture " + std::string(bridge::to_string(s.bridge.rupture)) : ""));
    say("bridges to the floor and cone", !s.wet || !s.wet_walls ? "no" : "yes, " + named(dem::wall_curve_source(s)));
    if (s.wet && s.viscosity_pa_s > 0)
        say("normal lubrication", s.lubrication == dem::Lubrication::finite_volume
                                      ? "finite volume (Pitois et al. 2000): squeezed out to the meniscus"
                                      : "unbounded 6 pi mu R*^2 v / s (LIGGGHTS' easo/capillary/viscous)");
    // Each part that acts, with its parameters as its table states them.
    for (const auto& part : parts)
        if (part.active(s))
            for (const auto& p : part.parameters) add(std::string(p.label), p.get(s), std::string(p.unit));
    say("engine of the lift and spread", s.liggghts_ranks > 0 ? "LIGGGHTS 3.8 under mpirun, " + std::to_string(s.liggghts_ranks) +
                                                                     " ranks (the fill poured and settled by demscale)"
                                                               : "demscale");
    add("time step (fine run)", s.dt_s * 1e6, "us");
    add("gravity", s.gravity, "m/s^2");
    t.rows.push_back({"settle / spread time limits", format_short(s.settle_time_s) + " / " + format_short(s.spread_time_s),
                      std::string("s")});
    add("at rest: this share of the particles", s.rest_quantile, "1");
    add("... slower than", s.rest_speed_m_per_s, "m/s");
    add("... for", s.rest_duration_s, "s");
    return t;
}

}  // namespace demscale::report
