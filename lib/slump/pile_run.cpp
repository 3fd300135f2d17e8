#include "slump/pile_run.hpp"

#include <algorithm>
#include <cmath>

#include "core/input_error.hpp"

namespace demscale::slump {

namespace {

double total_mass(const dem::Particles& p) {
    double m = 0;
    for (double x : p.mass) m += x;
    return m;
}

std::string pct(double x) { return format_short(100 * x, 2) + " %"; }

}  // namespace

std::optional<double> PileRun::slump_over_height() const {
    if (!fill_height) return std::nullopt;
    return (*fill_height - final.height) / *fill_height;
}

PileRun measure_pile_run(const dem::Particles& pile, const dem::Particles* fill, const SlumpScene& s, double sf, const std::string& sf_field) {
    PileRun r;
    // The largest sphere: one radius, a sieve's largest class or a lognormal's cut, in any pile of
    // the scene (a median would move with the mix of a distribution's classes).
    r.largest_radius = *std::max_element(pile.radius.begin(), pile.radius.end());
    const double expected = largest_radius(s);
    if (std::abs(r.largest_radius / expected - 1) > 0.02)
        throw InputError(sf_field, format_number(sf),
                         "the S_f of the file's spheres: their largest radius " + format_short(r.largest_radius * 1e3) + " mm is S_f " +
                             format_short(r.largest_radius / expected * sf, 3) + " of the scene's " + format_short(expected / sf * 1e3) + " mm");
    r.final = measure_pile(pile, s);
    r.pile_mass = total_mass(pile);
    r.fill_mass = r.pile_mass;
    if (fill) {
        r.fill_height = measure_pile(*fill, s).height;
        r.fill_mass = total_mass(*fill);
        // Spheres that left the domain, or floor grains counted in one file and not the other.
        if (std::abs(r.pile_mass / r.fill_mass - 1) > 0.005)
            r.warnings.push_back("the pile's mass differs from the fill's by " + pct(r.pile_mass / r.fill_mass - 1) +
                                 ": spheres lost, or floor grains in one file only (dump the pile's group)");
    }
    // Every fill of a scene holds one mass at every S_f (docs/slump-measures.md); a run that did not
    // compares unlike with like.
    const double target = fill_mass(s);
    if (std::abs(r.fill_mass / target - 1) > 0.01)
        r.warnings.push_back(std::string(fill ? "the fill" : "the pile") + " weighs " + format_short(r.fill_mass * 1e3) + " g, " +
                             pct(r.fill_mass / target - 1) + " from the scene's fill of " + format_short(target * 1e3) +
                             " g: not a same-mass fill of this scene");
    return r;
}

RunRow pile_run_row(const PileRun& run, double sf, double gamma, long seed, const SlumpScene& s, const std::string& fill_field) {
    const auto slump = run.slump_over_height();
    if (!slump) throw InputError(fill_field, "(not given)", "the settled fill the pile was lifted from: a runs row needs the slump over the fill's height");
    RunRow row;
    row.sf = sf, row.gamma = gamma, row.seed = seed;
    row.slump_over_height = *slump;
    row.spread_over_d0 = run.final.spread / s.bottom_diameter_m;
    return row;
}

}  // namespace demscale::slump
