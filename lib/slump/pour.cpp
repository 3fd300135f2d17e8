#include "slump/pour.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "core/input_error.hpp"
#include "dem/sphere_grid.hpp"

namespace demscale::slump {

namespace {

constexpr double insertion_fraction = 0.3;  // loose enough for random sequential addition (jams near 0.38)
constexpr int max_batches = 8;
constexpr double max_fill_shortfall = 0.005;  // of the target mass

double sphere_volume(double r) { return 4.0 / 3.0 * M_PI * r * r * r; }

double pile_top(const SlumpScene& s, const dem::Particles& pile) {
    double top = s.rough_floor ? 2 * s.radius_m : 0;  // above the rough floor's grains
    for (std::size_t i = 0; i < pile.size(); ++i) top = std::max(top, pile.position[i].z() + pile.radius[i]);
    return top;
}

// Radius of the region a centre at height z may occupy: inside the cone below its top, inside the
// column of the top opening above it, with a clearance of 5 % of the largest radius from the wall.
double reach_at(const SlumpScene& s, double z) {
    return std::min(cone_radius_at(s, std::min(z, s.height_m)), cone_radius_at(s, s.height_m)) - 1.05 * largest_radius(s);
}

// Inside the cone's wall, and wholly under its top (a pour's count) or with its centre under the top
// (the fill: a sphere whose top pokes above the rim is still held by the wall below its centre).
// wall_overlap: how far into the wall a sphere may press, / R (a sphere resting on the wall
// presses in by its Hertz overlap, a few % of R).
bool inside_cone(const SlumpScene& s, const dem::Vec3& x, double r, bool centre_below_top = false, double wall_overlap = 1e-9) {
    return (centre_below_top ? x.z() <= s.height_m : x.z() + r <= s.height_m) &&
           std::hypot(x.x(), x.y()) + r <= cone_radius_at(s, std::max(x.z(), 0.0)) + wall_overlap * r;
}

// Solid volume of the spheres wholly inside the cone, m³.
double solid_in_cone(const SlumpScene& s, const dem::Particles& pile) {
    double v = 0;
    for (std::size_t i = 0; i < pile.size(); ++i)
        if (inside_cone(s, pile.position[i], pile.radius[i])) v += sphere_volume(pile.radius[i]);
    return v;
}

}  // namespace

std::size_t pour_batch_size(const SlumpScene& s, const dem::Particles& pile) {
    const double r = s.radius_m, vp = sphere_volume(r) * mean_volume_ratio(s.sizes);  // the mean sphere's volume
    // The fill's volume plus a layer one diameter thick at a solid fraction of 0.5 over the cone's
    // cross-section at the fill height: enough to cut the target from at a level that does not
    // depend on how loosely this radius packs.
    const double target = fill_mass(s) / s.material.density + 0.5 * M_PI * std::pow(cone_radius_at(s, s.fill_height_m), 2) * 2 * r;
    const double missing = target - solid_in_cone(s, pile);
    return missing > 0 ? static_cast<std::size_t>(std::ceil(missing / vp)) : 0;
}

dem::Particles insert_batch(const SlumpScene& s, const dem::Particles& pile, std::size_t count, unsigned stream) {
    const double r_max = largest_radius(s);
    std::mt19937_64 rng((static_cast<std::uint64_t>(s.seed) << 32) ^ (0x9e3779b9ull * (stream + 1)));
    // The radii have a stream of their own: with one radius the positions are drawn as they always were.
    std::mt19937_64 size_rng((static_cast<std::uint64_t>(s.seed) << 32) ^ (0x85ebca6bull * (stream + 1)));
    std::uniform_real_distribution<double> unit(0, 1);
    dem::SphereGrid grid(2.02 * r_max);
    std::vector<double> radii;  // of the grid's centres, by index
    for (std::size_t i = 0; i < pile.size(); ++i) grid.add(pile.position[i]), radii.push_back(pile.radius[i]);
    // 1 % of the pair's radii clear of every neighbour.
    auto clear = [&](const dem::Vec3& x, double r) {
        bool overlaps = false;
        grid.near(x, 1.01 * (r + r_max), [&](std::size_t j, const dem::Vec3& y) {
            const double gap = 1.01 * (r + radii[j]);
            overlaps = overlaps || (x - y).squaredNorm() < gap * gap;
        });
        return !overlaps;
    };
    dem::Particles batch;
    // Each sphere's radius is drawn once and kept until it finds room: large spheres are not
    // dropped for being harder to place, so the batch follows the distribution.
    double r = s.radius_m * draw_radius_ratio(s.sizes, size_rng);
    // Slabs one largest diameter thick, upward from the pile's top, each filled to the insertion fraction.
    double z0 = pile_top(s, pile) + 1.05 * r_max;
    for (int slab = 0; batch.size() < count; ++slab) {
        if (slab > 100000) throw std::runtime_error("pour: no room to insert spheres above the pile");
        const double lo = z0 + slab * 2 * r_max, hi = lo + 2 * r_max;
        const double reach = reach_at(s, hi);  // the narrower end of the slab
        if (reach <= 0) throw std::runtime_error("pour: the cone's top opening is narrower than a sphere");
        const double capacity = insertion_fraction * M_PI * reach * reach * 2 * r_max / (sphere_volume(s.radius_m) * mean_volume_ratio(s.sizes));
        const auto want = std::min<std::size_t>(count - batch.size(), static_cast<std::size_t>(std::max(1.0, capacity)));
        for (std::size_t placed = 0, tries = 0; placed < want && tries < 200 * want; ++tries) {
            const double rho = reach * std::sqrt(unit(rng)), phi = 2 * M_PI * unit(rng);
            const dem::Vec3 x(rho * std::cos(phi), rho * std::sin(phi), lo + (hi - lo) * unit(rng));
            if (!clear(x, r)) continue;
            grid.add(x), radii.push_back(r);
            batch.add(x, r, s.material.density);
            ++placed;
            r = s.radius_m * draw_radius_ratio(s.sizes, size_rng);
        }
    }
    return batch;
}

dem::Particles cut_to_mass(const SlumpScene& s, const dem::Particles& pile) {
    std::vector<std::size_t> inside, at_wall;  // wholly inside; pressed into the wall by less than 5 % of R
    for (std::size_t i = 0; i < pile.size(); ++i)
        if (inside_cone(s, pile.position[i], pile.radius[i], true)) inside.push_back(i);
        else if (inside_cone(s, pile.position[i], pile.radius[i], true, 0.05)) at_wall.push_back(i);
    auto by_height = [&](std::vector<std::size_t>& v) {
        std::stable_sort(v.begin(), v.end(), [&](std::size_t a, std::size_t b) { return pile.position[a].z() < pile.position[b].z(); });
    };
    by_height(inside), by_height(at_wall);
    const double target = fill_mass(s);
    // Each size bin to its share of the mass, the lowest spheres first. Those resting on the wall
    // are left out, as they always were for one radius (docs/limitations.md); a size distribution's
    // bin that falls short without them takes them: the wall holds a share of the mass that grows
    // with R (a layer one sphere thick), so its large spheres would be too few. Then, should the
    // mass still fall short, the lowest of the rest up to the total.
    const auto shares = bin_mass_shares(s.sizes);
    std::vector<double> bin_mass(shares.size(), 0.0);
    std::vector<bool> taken(pile.size(), false);
    double mass = 0;
    auto take_lowest = [&](const std::vector<std::size_t>& from, bool by_bin) {
        for (std::size_t i : from) {
            if (taken[i]) continue;
            const double m = s.material.density * sphere_volume(pile.radius[i]);
            const std::size_t bin = size_bin(s.sizes, pile.radius[i] / s.radius_m);
            if (by_bin ? bin_mass[bin] + 0.5 * m > shares[bin] * target : mass + 0.5 * m > target) continue;  // the count nearest the target
            taken[i] = true, bin_mass[bin] += m, mass += m;
        }
    };
    take_lowest(inside, true);
    if (!s.sizes.monodisperse()) take_lowest(at_wall, true);
    take_lowest(inside, false);
    std::vector<std::size_t> all = inside;
    all.insert(all.end(), at_wall.begin(), at_wall.end());
    by_height(all);
    dem::Particles kept;
    for (std::size_t i : all)  // lowest first
        if (taken[i]) {
            const auto j = kept.add(pile.position[i], pile.radius[i], s.material.density, pile.velocity[i], pile.species[i]);
            kept.angular_velocity[j] = pile.angular_velocity[i];
        }
    // Short by up to half a sphere, or 0.5 % of the target, is the same mass within the study's 1 %.
    const double sphere = s.material.density * sphere_volume(s.radius_m);
    if (target - mass > std::max(0.5 * sphere, max_fill_shortfall * target))
        throw FillShortfall("fill: the cone holds " + format_short(mass * 1e3, 4) + " g of spheres of radius " +
                                 format_short(s.radius_m * 1e3, 3) + " mm, short of the fill's " + format_short(target * 1e3, 4) +
                                 " g by more than 0.5 % (the pour jams in the top opening, or the fill does not fit under the cone's "
                                 "top at this radius)");
    return kept;
}

dem::Particles pour_fill(const SlumpScene& s, const std::function<dem::Particles(dem::Particles)>& settle) {
    dem::Particles pile;
    for (int batch = 0; batch < max_batches; ++batch) {
        const std::size_t n = pour_batch_size(s, pile);
        if (n == 0) break;
        pile.append(insert_batch(s, pile, n, static_cast<unsigned>(batch)));
        pile = settle(std::move(pile));
    }
    return cut_to_mass(s, pile);
}

}  // namespace demscale::slump
