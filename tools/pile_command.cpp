// The pile command: the one door for piles made by any engine. It measures a LIGGGHTS or LAMMPS
// dump, a CSV of spheres or demscale's own particle files with the slump test's own measures, and
// can add the run to a runs file that check-exponent --runs and estimate-exponent --runs judge.
#include <cmath>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli_common.hpp"
#include "core/input_error.hpp"
#include "io/pile_file.hpp"
#include "slump/coarse_grain.hpp"
#include "slump/motion.hpp"
#include "slump/pile_run.hpp"

namespace demscale::cli {

namespace {

struct Options {
    std::string scene = default_scene;
    std::string dump, fill, append_runs;
    std::string format = "json";
    double sf = 1;
    std::optional<double> gamma, exponent;
    std::optional<long> seed;
};

// The run's own surface tension for its runs row: --gamma, or the scene's γ S_f^k from --exponent,
// or, for a fine run, the scene's γ (0 for a dry scene).
double run_gamma(const Options& o, const slump::SlumpScene& fine) {
    if (o.gamma) return *o.gamma;
    const double gamma = fine.wet ? fine.liquid.surface_tension_n_per_m : 0.0;
    if (o.exponent) {
        require_finite(*o.exponent, "--exponent");
        return gamma * std::pow(o.sf, *o.exponent);
    }
    if (o.sf != 1.0)
        throw InputError("--gamma", "(not given)", "the coarse run's own surface tension in N/m (0: dry), or --exponent K for the scene's gamma S_f^K");
    return gamma;
}

nlohmann::ordered_json pile_json(const Options& o, const io::PileFile& pile, const slump::PileRun& r, const slump::SlumpScene& s) {
    const auto mm = [](double x) { return x * 1e3; };
    const auto maybe = [](std::optional<double> x) { return x ? nlohmann::ordered_json(*x) : nlohmann::ordered_json(); };
    nlohmann::ordered_json j;
    j["pile_file"] = display_path(o.dump);
    j["pile_format"] = pile.kind;
    j["snapshots"] = pile.snapshots;  // a dump's; its last is the pile
    j["fill_file"] = o.fill.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(display_path(o.fill));
    j["scene"] = display_path(o.scene);
    j["sf"] = o.sf;
    j["particles"] = pile.particles.size();
    j["largest_radius_mm"] = mm(r.largest_radius);
    j["fill_mass_g"] = r.fill_mass * 1e3;
    j["fill_mass_target_g"] = slump::fill_mass(s) * 1e3;
    j["pile_mass_g"] = r.pile_mass * 1e3;
    j["fill_height_mm"] = r.fill_height ? nlohmann::ordered_json(mm(*r.fill_height)) : nlohmann::ordered_json();
    j["final_height_mm"] = mm(r.final.height);
    j["slump_mm"] = r.fill_height ? nlohmann::ordered_json(mm(*r.fill_height - r.final.height)) : nlohmann::ordered_json();
    j["slump_over_fill_height"] = maybe(r.slump_over_height());
    j["spread_mm"] = mm(r.final.spread);
    j["spread_over_d0"] = r.final.spread / s.bottom_diameter_m;
    j["repose_angle_deg"] = maybe(r.final.repose_angle_deg);
    j["final_height_top_mm"] = mm(r.final.height_top);  // sphere-level measures, for comparison
    j["spread_d95_mm"] = mm(r.final.spread_d95);
    j["spread_max_mm"] = mm(r.final.spread_max);
    j["profile"] = nlohmann::ordered_json::array();
    for (const auto& q : r.final.profile) j["profile"].push_back({{"radius_mm", mm(q.radius)}, {"height_mm", mm(q.height)}});
    j["warnings"] = r.warnings;
    return j;
}

int run_pile(const Options& o) {
    const auto format = io::parse_format(o.format, "--format");
    if (format != io::Format::json && format != io::Format::text) throw InputError("--format", o.format, "json or text");
    if (!(o.sf >= 1)) throw InputError("--sf", format_number(o.sf), "a scale factor >= 1 (1: the fine scene)");
    const auto fine = slump::load_slump_scene(o.scene);  // measures only: nothing runs
    const auto scene = slump::coarse_grained(fine, {o.sf, 1.0, {}});  // the radius and grid at S_f
    const auto pile = io::read_pile_file("--dump", o.dump, scene.material.density);
    std::optional<io::PileFile> fill;
    if (!o.fill.empty()) fill = io::read_pile_file("--fill", o.fill, scene.material.density);
    const auto run = slump::measure_pile_run(pile.particles, fill ? &fill->particles : nullptr, scene, o.sf, "--sf");
    // At rest by the scene's criterion in this one snapshot (slump/motion.hpp); unknown without velocities.
    std::optional<bool> at_rest;
    if (pile.velocities)
        at_rest = slump::quantile_slower_than(pile.particles, pile.particles.size(), scene.rest_speed_m_per_s, scene.rest_quantile);
    if (!o.append_runs.empty()) {
        if (!o.seed) throw InputError("--seed", "(not given)", "the run's seed, an integer >= 0 (a runs row names its pile)");
        auto row = slump::pile_run_row(run, o.sf, run_gamma(o, fine), *o.seed, scene, "--fill");
        row.at_rest = at_rest.value_or(true);
        slump::append_run("--append-runs", o.append_runs, row, fine.name);
    }
    auto j = pile_json(o, pile, run, scene);
    j["at_rest"] = at_rest ? nlohmann::ordered_json(*at_rest) : nlohmann::ordered_json();  // null: no velocities in the file
    if (format == io::Format::json) {
        std::cout << j.dump(2) << "\n";
    } else {
        for (const auto& [k, v] : j.items())
            if (k != "warnings" && k != "profile") std::cout << k << ": " << v.dump() << "\n";
    }
    for (const auto& w : run.warnings) std::cerr << "warning: " << w << "\n";
    if (!o.append_runs.empty()) std::cerr << "added the run to " << o.append_runs << "\n";
    return 0;
}

}  // namespace

std::vector<Command> pile_commands(CLI::App& app) {
    auto o = std::make_shared<Options>();
    auto* pile = app.add_subcommand("pile", "measure a pile made by any engine (LIGGGHTS/LAMMPS dump, CSV of spheres, demscale's files) "
                                            "as slump measures its own; optionally add it to a runs file");
    pile->add_option("--dump", o->dump, "the final pile: a text dump (ITEM: ATOMS with x y z radius in any order), "
                                        "a CSV (x,y,z,radius in m or x_mm,...,radius_mm), or a demscale particle file")->required();
    pile->add_option("--fill", o->fill, "the settled fill the pile was lifted from (same formats): for the slump over the fill's height");
    pile->add_option("--scene", o->scene, "the scene the run was made of (cone, radius, density; default: data/scenes/kantro_wet.toml)");
    pile->add_option("--sf", o->sf, "the run's scale factor S_f (its spheres' radius over the scene's)")->capture_default_str();
    pile->add_option("--format", o->format, "json | text")->capture_default_str();
    pile->add_option("--append-runs", o->append_runs, "add the run to this runs file (created when absent; docs/file-formats.md)");
    pile->add_option("--seed", o->seed, "the run's seed (with --append-runs)")->check(CLI::NonNegativeNumber);
    auto* gamma = pile->add_option("--gamma", o->gamma, "the run's own surface tension, N/m (0: dry; with --append-runs)")
                      ->check(finite_non_negative);
    pile->add_option("--exponent", o->exponent, "instead of --gamma: the run's surface tension is the scene's gamma S_f^K")
        ->excludes(gamma);
    return {{pile, [o] { return run_pile(*o); }}};
}

}  // namespace demscale::cli
