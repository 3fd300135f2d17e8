#include "slump/liggghts_export.hpp"

#include "dem/law_parts.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <vector>

#include "bridge/mikami.hpp"
#include "dem/bridge_law.hpp"
#include "io/atomic_file.hpp"
#include "slump/fill.hpp"
#include "slump/scene_bridges.hpp"

namespace demscale::slump {

namespace fs = std::filesystem;

namespace {

// The box a LIGGGHTS user would fit to the scene (its neighbour bins cover the whole box; a sphere
// that leaves it is lost): twice the radius of the fill spread out as one layer of spheres at solid
// fraction 0.6, or the rough floor; high enough for the lifted cone. m.
struct Box {
    double half_width, height;
};
Box fitted_box(const slump::SlumpScene& sc, const dem::Particles& p) {
    double solid = 0;
    for (std::size_t i = 0; i < p.size(); ++i) solid += 4.0 / 3.0 * std::numbers::pi * std::pow(p.radius[i], 3);
    const double layer = std::sqrt(solid / 0.6 / (2 * sc.radius_m) / std::numbers::pi);
    const double floor = sc.rough_floor ? 0.5 * sc.rough_floor_diameter_m + 2 * sc.radius_m : 0.0;
    return {std::max({2 * layer, floor, 0.5 * sc.bottom_diameter_m + 2 * sc.radius_m}), 1.1 * (sc.height_m + sc.lift_height_m)};
}

std::string data_file(const dem::Particles& p, const Box& box) {
    std::ostringstream s;
    s.precision(17);
    s << "LIGGGHTS data file written by demscale (settled slump fill)\n\n"
      << p.size() << " atoms\n1 atom types\n\n"
      << -box.half_width << ' ' << box.half_width << " xlo xhi\n" << -box.half_width << ' ' << box.half_width << " ylo yhi\n"
      << "-0.001 " << box.height << " zlo zhi\n\nAtoms\n\n";
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double rho = p.mass[i] / (4.0 / 3.0 * std::numbers::pi * std::pow(p.radius[i], 3));
        s << i + 1 << " 1 " << 2 * p.radius[i] << ' ' << rho << ' ' << p.position[i].x() << ' ' << p.position[i].y() << ' '
          << p.position[i].z() << '\n';
    }
    s << "\nVelocities\n\n";
    for (std::size_t i = 0; i < p.size(); ++i) {
        const auto& v = p.velocity[i];
        const auto& w = p.angular_velocity[i];
        s << i + 1 << ' ' << v.x() << ' ' << v.y() << ' ' << v.z() << ' ' << w.x() << ' ' << w.y() << ' ' << w.z() << '\n';
    }
    return s.str();
}

// The open frustum as triangles: 96 segments around, one band (its meridian is straight).
std::string cone_stl(const slump::SlumpScene& sc) {
    constexpr int n = 96;
    const double rb = 0.5 * sc.bottom_diameter_m, rt = 0.5 * sc.top_diameter_m, h = sc.height_m;
    std::ostringstream s;
    s.precision(12);
    auto vertex = [&](double r, double phi, double z) {
        s << "      vertex " << r * std::cos(phi) << ' ' << r * std::sin(phi) << ' ' << z << '\n';
    };
    auto facet = [&](double r1, double p1, double z1, double r2, double p2, double z2, double r3, double p3, double z3) {
        s << "  facet normal 0 0 0\n    outer loop\n";
        vertex(r1, p1, z1), vertex(r2, p2, z2), vertex(r3, p3, z3);
        s << "    endloop\n  endfacet\n";
    };
    s << "solid cone\n";
    for (int k = 0; k < n; ++k) {
        const double a = 2 * std::numbers::pi * k / n, b = 2 * std::numbers::pi * (k + 1) / n;
        facet(rb, a, 0, rb, b, 0, rt, b, h);
        facet(rb, a, 0, rt, b, h, rt, a, h);
    }
    s << "endsolid cone\n";
    return s.str();
}

// A wet scene in LIGGGHTS-PUBLIC 3.8: `cohesion easo/capillary/viscous`, Soulié et al.'s (2006)
// form of Mikami's regression, between particles only (it refuses walls). Each quantity mapped
// explicitly (docs/dem-engine.md, "LIGGGHTS export"); what cannot be matched is listed in `notes`.
struct WetDeck {
    std::string properties;           // fix property/global lines
    std::vector<std::string> notes;   // the deck header's list of differences
};
WetDeck wet_deck(const slump::SlumpScene& sc) {
    WetDeck w;
    const double r = sc.radius_m, vhat = bridge_vhat(sc), theta = sc.liquid.contact_angle.radians();
    // Liquid per particle: each sphere gives (1 − √(1 − R_j²/(R_i + R_j)²))/2 of its liquid to a
    // bridge (0.0670 for equal spheres), so the bridge holds V when each sphere carries V/0.1340.
    auto given = [](double ri, double rj) { return (1 - std::sqrt(1 - rj * rj / ((ri + rj) * (ri + rj)))) / 2; };
    auto sphere_volume = [](double x) { return 4.0 / 3.0 * std::numbers::pi * x * x * x; };
    const double content = vhat * r * r * r / (2 * given(r, r) * sphere_volume(r));
    // LIGGGHTS takes θ_eff = θ_i·θ_j/2 (radians) for the pair; writing √(2θ) makes θ_eff the scene's θ.
    const double theta_written_deg = std::sqrt(2 * theta) * 180 / std::numbers::pi;
    // Its rupture is Lian's (1 + θ/2)·V^(1/3); the neighbour list must reach that far.
    const double rupture_lian = bridge::rupture_hhat(vhat, sc.liquid.contact_angle, bridge::RuptureLaw::lian1993);
    const double min_gap_over_rstar = 2 * sc.min_gap_ratio;  // LIGGGHTS measures s_min over R* = R/2
    int property = 0;
    auto prop = [&](const std::string& name, const std::string& kind, double value) {
        std::ostringstream l;
        l.precision(10);
        l << "fix liquid" << ++property << " all property/global " << name << " " << kind << " " << value << "\n";
        w.properties += l.str();
    };
    prop("surfaceLiquidContentInitial", "scalar", content);
    prop("surfaceTension", "scalar", sc.liquid.surface_tension_n_per_m);
    prop("contactAngle", "peratomtype", theta_written_deg);
    prop("fluidViscosity", "scalar", sc.viscosity_pa_s);
    prop("minSeparationDistanceRatio", "scalar", min_gap_over_rstar);
    prop("maxSeparationDistanceRatio", "scalar", 1 + 0.55 * rupture_lian);

    const double lnv = std::log(vhat), t2 = theta * theta;
    const double fit = bridge::mikami_fhat(bridge::mikami_coefficients(vhat, sc.liquid.contact_angle), 0.0);  // Mikami, at contact
    const double soulie = std::exp((-0.148 * lnv - 0.96) * t2 - 0.0082 * lnv + 0.48) + 0.0018 * lnv + 0.078;  // Soulié, at contact
    const double scene_rupture = bridge::rupture_hhat(vhat, sc.liquid.contact_angle, sc.bridge.rupture);
    auto pct = [](double x) { return format_short(100 * x, 3) + " %"; };
    w.notes = {
        "WET: cohesion easo/capillary/viscous (Soulie et al. 2006's form of Mikami's regression), V^ = " + format_short(vhat, 4) +
            " per bridge as in demscale (Eq. 5): surfaceLiquidContentInitial = V / (0.1340 x sphere volume) = " + format_short(content, 4),
        "force: pi gamma sqrt(Ri Rj) (exp(A s/R2 + B) + C), as demscale's pi R gamma F^ for equal spheres; Soulie's B and C differ "
            "from Mikami's: at contact " + pct(soulie / fit - 1) + " against the mikami1998 form",
        "rupture: Lian (1 + theta/2) V^(1/3) = " + format_short(rupture_lian, 4) + " R; the scene's " +
            std::string(bridge::to_string(sc.bridge.rupture)) + " law gives " + format_short(scene_rupture, 4) + " R (" +
            pct(rupture_lian / scene_rupture - 1) + ")",
        "contact angle: written as sqrt(2 theta) = " + format_short(theta_written_deg, 4) +
            " deg so that LIGGGHTS' pair angle theta_i theta_j / 2 (rad) equals the scene's " +
            format_short(sc.liquid.contact_angle.degrees(), 3) + " deg",
        "viscous part: fluidViscosity = " + format_short(sc.viscosity_pa_s) +
            " Pa s (0: off); minSeparationDistanceRatio = s_min / R* = 2 x liquid.min_gap_ratio; normal lubrication "
            "UNBOUNDED, 6 pi mu R*^2 v / s (LIGGGHTS has no finite-volume factor)" +
            (sc.viscosity_pa_s > 0 && sc.lubrication == dem::Lubrication::finite_volume
                 ? std::string("; the demscale scene uses Pitois et al.'s finite-volume form: set liquid.lubrication = \"unbounded\" "
                               "to compare like with like")
                 : std::string("")),
        "liquid: carried per particle and shared evenly again at rupture (equal spheres: nothing moves); demscale gives every bridge V",
    };
    if (!sc.sizes.monodisperse()) {
        // Unequal spheres: LIGGGHTS scales the force by sqrt(Ri Rj) and fills a bridge from each
        // sphere's own liquid; demscale takes R* = 2 Ri Rj / (Ri + Rj) and V = V^ R*^3. Both at the
        // scene's smallest and largest spheres:
        const double r1 = smallest_radius(sc), r2 = largest_radius(sc), r_star = 2 * r1 * r2 / (r1 + r2);
        const double v_liggghts = content * (sphere_volume(r1) * given(r1, r2) + sphere_volume(r2) * given(r2, r1));
        const double v_demscale = vhat * r_star * r_star * r_star;
        w.notes.push_back("unequal spheres (" + describe(sc.sizes) + "): between the smallest and largest, " + format_short(r1 * 1e3, 3) +
                          " and " + format_short(r2 * 1e3, 3) + " mm, LIGGGHTS' force scale pi gamma sqrt(Ri Rj) is " +
                          pct(std::sqrt(r1 * r2) / r_star - 1) + " against demscale's pi gamma R*, R* = 2 Ri Rj / (Ri + Rj); its bridge "
                          "holds each sphere's share of its own liquid, " + pct(v_liggghts / v_demscale - 1) + " against demscale's V^ R*^3");
    }
    if (sc.wet_walls) w.notes.push_back("walls DRY here: easo/capillary/viscous refuses walls; the demscale scene has wet walls");
    // A curve source with no LIGGGHTS words of its own has no equivalent there: said, not hidden.
    if (const auto& source = dem::particle_curve_source(sc); source.liggghts.empty())
        w.notes.push_back("the scene's bridges follow " + std::string(source.label) + " (" + std::string(source.value) +
                          "): LIGGGHTS has no equivalent, the deck uses the fit above");
    return w;
}

}  // namespace

DeckSteps deck_steps(const SlumpScene& sc) {
    const long spread = std::lround(sc.spread_time_s / sc.dt_s);
    // At most the whole spread between checks: a rest duration longer than the spread (slump
    // --fixed-time) then never rests, and the deck runs the whole spread.
    const double check = std::clamp(sc.rest_duration_s / 4 / sc.dt_s, 1.0, static_cast<double>(std::max(1L, spread)));
    return {std::lround(sc.lift_height_m / sc.lift_speed_m_per_s / sc.dt_s), spread, std::lround(check)};
}

namespace {

// particles: the pile's count; atoms after it are the rough floor's grains, which only the pile touches.
std::string deck(const slump::SlumpScene& sc, std::size_t particles, std::size_t grains, bool stop_at_rest) {
    const auto [lift_steps, spread_steps, check] = deck_steps(sc);
    // demscale's epsd is LIGGGHTS' epsd3 with Ai's prefactor 2.25 and the scene's rolling damping η_r.
    const auto model = sc.rolling_model;
    const std::string rolling = model == slump::RollingModel::constant_torque ? " rolling_friction cdt"
                                : model == slump::RollingModel::epsd2         ? " rolling_friction epsd2"
                                                                              : " rolling_friction epsd3";
    // The acting parts' own pair style words (normal, tangential and cohesion models) go before the
    // rolling model, their keyword/value settings after all models; a part without words says so.
    // The bridge's words go to the particle pairs only (LIGGGHTS refuses it on walls).
    std::string models, wall_models, settings;
    std::vector<std::string> unmatched;
    for (const auto& part : dem::law_parts())
        if (part.active(sc)) {
            if (!part.liggghts_model.empty()) models += " " + std::string(part.liggghts_model);
            if (!part.liggghts_model.empty() && part.liggghts_walls) wall_models += " " + std::string(part.liggghts_model);
            if (!part.liggghts_setting.empty()) settings += " " + std::string(part.liggghts_setting);
            if (!part.liggghts_note.empty()) unmatched.push_back(std::string(part.name) + ": " + std::string(part.liggghts_note));
        }
    const std::string rolling_words = sc.rolling_resistance ? rolling : std::string();
    auto words = [](const std::string& w) { return w.empty() ? w : w.substr(1); };
    const std::string laws = words(models + rolling_words + settings);
    const std::string wall_laws = words(wall_models + rolling_words + settings);
    const WetDeck wet = sc.wet ? wet_deck(sc) : WetDeck{};
    std::ostringstream s;
    s << "# LIGGGHTS input deck written by demscale export liggghts: " << sc.name << ", " << particles << " spheres\n"
      << "# Same laws, parameters, time step, lift and spread as demscale's run from the same settled fill.\n";
    if (stop_at_rest)
        s << "# Spreading stops at rest by demscale's criterion (checked every " << check << " steps) or after spread_time_s ("
          << sc.spread_time_s << " s); compare with demscale slump --start settled.csv.\n";
    else
        s << "# Spreading runs the scene's whole spread_time_s (" << sc.spread_time_s
          << " s): LIGGGHTS has no rest criterion; compare with demscale slump --start settled.csv --fixed-time.\n";
    for (const auto& n : wet.notes) s << "# " << n << "\n";
    for (const auto& n : unmatched) s << "# " << n << "\n";
    // Everything that moves acts on group `pile`; the floor's grains (if any) are never integrated.
    const std::string pile = grains == 0 ? "all" : "pile";
    s << "atom_style granular\natom_modify map array\nboundary f f f\nnewton off\ncommunicate single vel yes\nunits si\n"
      << "read_data particles.data\n";
    if (grains > 0) s << "group pile id <> 1 " << particles << "\n# atoms " << particles + 1 << " to " << particles + grains
                      << ": the rough floor's grains, held in place (no integration)\n";
    s
      << "neighbor " << sc.skin_m << " bin\nneigh_modify delay 0\n";
    // The material: every parameter with a LIGGGHTS name of each law part that acts, from its table,
    // then the liquid's (mapped above).
    int property = 0;
    for (const auto& part : dem::law_parts()) {
        if (!part.active(sc)) continue;
        if (!part.liggghts_extra.empty()) s << "fix m" << ++property << " all " << part.liggghts_extra << "\n";
        for (const auto& p : part.parameters) {
            if (p.liggghts.empty()) continue;
            s << "fix m" << ++property << " all property/global " << p.liggghts
              << (p.liggghts_kind == dem::LiggghtsKind::per_type        ? " peratomtype "
                  : p.liggghts_kind == dem::LiggghtsKind::per_type_pair ? " peratomtypepair 1 "
                                                                        : " scalar ")
              << p.get(sc) << "\n";
        }
    }
    s << wet.properties;
    s << "pair_style gran " << laws << "\npair_coeff * *\n"
      << "timestep " << sc.dt_s << "\n"
      << "fix gravi " << pile << " gravity " << sc.gravity << " vector 0.0 0.0 -1.0\n"
      << "fix cone all mesh/surface file cone.stl type 1\n"
      << "fix walls " << pile << " wall/gran " << wall_laws << " mesh n_meshes 1 meshes cone\n"
      << "fix floor " << pile << " wall/gran " << wall_laws << " primitive type 1 zplane 0.0\n"
      << "fix integr " << pile << " nve/sphere\n"
      << "thermo " << std::max(1L, (lift_steps + spread_steps) / 20) << "\nthermo_style custom step atoms ke\n"
      << "# lift the cone " << sc.lift_height_m * 1e3 << " mm at " << sc.lift_speed_m_per_s << " m/s, then remove it\n"
      << "fix lift all move/mesh mesh cone linear 0.0 0.0 " << sc.lift_speed_m_per_s << "\n"
      << "run " << lift_steps << "\n"
      << "unfix lift\nunfix walls\nunfix cone\n";
    const std::string dump = "dump_modify final format \"%d %d %.17g %.17g %.17g %.17g %.17g %.17g %.17g\"\n";
    if (!stop_at_rest) {
        s << "dump final " << pile << " custom " << lift_steps + spread_steps << " final.dump id type x y z radius vx vy vz\n"
          << dump << "run " << spread_steps << "\n";
        return s.str();
    }
    // demscale's rest criterion (slump/motion.hpp) in LIGGGHTS' input language: the count of spheres
    // at the rest speed or faster, after every `check` steps; at rest after five passes in a row.
    const auto allowed = static_cast<long>(std::floor((1 - sc.rest_quantile) * static_cast<double>(particles) + 1e-9));
    s << "# spread until at rest: at most " << allowed << " of the " << particles << " spheres at " << sc.rest_speed_m_per_s
      << " m/s or faster, at five checks " << check << " steps apart (" << sc.rest_duration_s << " s)\n"
      << "variable speed atom sqrt(vx*vx+vy*vy+vz*vz)\nvariable fast atom v_speed>=" << sc.rest_speed_m_per_s << "\n"
      << "compute nfast " << pile << " reduce sum v_fast\nthermo_style custom step atoms ke c_nfast\n"
      << "variable still equal 0\nvariable chunk loop " << (spread_steps + check - 1) / check << "\n"
      << "label spread\nrun " << check << "\nvariable nf equal c_nfast\n"
      << "if \"${nf} <= " << allowed << "\" then \"variable still equal $(v_still+1)\" else \"variable still equal 0\"\n"
      << "if \"${still} >= 5\" then \"jump SELF rested\"\nnext chunk\njump SELF spread\njump SELF ended\n"
      << "label rested\nvariable atstep equal step\nprint \"" << liggghts_rest_line << "${atstep}\"\nlabel ended\n"
      << "dump final " << pile << " custom 1 final.dump id type x y z radius vx vy vz\n" << dump << "run 0\n";
    return s.str();
}

}  // namespace

std::vector<fs::path> export_liggghts(const slump::SlumpScene& scene, const dem::Particles& settled, const fs::path& out_dir,
                                      bool stop_at_rest) {
    dem::Particles all = settled.mobile();
    const std::size_t pile = all.size();
    all.append(slump::floor_grains(scene));
    io::write_file_atomically(out_dir / "particles.data", data_file(all, fitted_box(scene, settled.mobile())));
    io::write_file_atomically(out_dir / "cone.stl", cone_stl(scene));
    io::write_file_atomically(out_dir / "in.slump", deck(scene, pile, all.size() - pile, stop_at_rest));
    return {out_dir / "in.slump", out_dir / "particles.data", out_dir / "cone.stl"};
}

}  // namespace demscale::slump
