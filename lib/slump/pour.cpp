#include "slump/pour.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "dem/sphere_grid.hpp"

namespace demscale::slump {

namespace {

constexpr double insertion_fraction = 0.3;  // loose enough for random sequential addition (jams near 0.38)
constexpr int max_batches = 8;

double sphere_volume(double r) { return 4.0 / 3.0 * M_PI * r * r * r; }

double pile_top(const SlumpScene& s, const dem::Particles& pile) {
    double top = s.rough_floor ? 2 * s.radius_m : 0;  // above the rough floor's grains
    for (std::size_t i = 0; i < pile.size(); ++i) top = std::max(top, pile.position[i].z() + pile.radius[i]);
    return top;
}

// Radius of the region a centre at height z may occupy: inside the cone below its top, inside the
// column of the top opening above it, with a clearance of 5 % of R from the wall.
double reach_at(const SlumpScene& s, double z) {
    return std::min(cone_radius_at(s, std::min(z, s.height_m)), cone_radius_at(s, s.height_m)) - 1.05 * s.radius_m;
}

}  // namespace

std::size_t pour_batch_size(const SlumpScene& s, const dem::Particles& pile) {
    const double r = s.radius_m, vp = sphere_volume(r), strike = s.fill_height_m;
    const double cover = 0.5 * M_PI * std::pow(cone_radius_at(s, strike), 2) * 2 * r;  // one layer, solid volume
    if (pile.size() == 0)  // about a loose fill's worth: a denser pile falls short and gets a second batch
        return static_cast<std::size_t>(std::ceil((0.45 * cone_volume_below(s, strike) + cover) / vp));
    // The pile's level: the 95th percentile of the sphere tops inside the cone (a sphere perched on
    // top does not count); its solid fraction below that level sizes the next batch.
    std::vector<double> tops;
    double above = 0;
    for (std::size_t i = 0; i < pile.size(); ++i) {
        const double top = pile.position[i].z() + pile.radius[i];
        if (pile.position[i].z() > strike - r) above += sphere_volume(pile.radius[i]);
        if (std::hypot(pile.position[i].x(), pile.position[i].y()) < cone_radius_at(s, std::min(top, s.height_m))) tops.push_back(top);
    }
    if (above >= cover || tops.empty()) return 0;
    std::sort(tops.begin(), tops.end());
    const double level = std::min(tops[static_cast<std::size_t>(0.95 * static_cast<double>(tops.size() - 1))], strike);
    double below = 0;
    for (double top : tops) below += top <= level ? vp : 0;
    const double fraction = std::clamp(below / cone_volume_below(s, level), 0.3, 0.64);
    const double missing = fraction * (cone_volume_below(s, strike) - cone_volume_below(s, level));
    return static_cast<std::size_t>(std::ceil((missing + cover - above) / vp));
}

dem::Particles insert_batch(const SlumpScene& s, const dem::Particles& pile, std::size_t count, unsigned stream) {
    const double r = s.radius_m, gap = 2.02 * r;  // 1 % of R clear of every neighbour
    std::mt19937_64 rng((static_cast<std::uint64_t>(s.seed) << 32) ^ (0x9e3779b9ull * (stream + 1)));
    std::uniform_real_distribution<double> unit(0, 1);
    dem::SphereGrid grid(gap);
    for (std::size_t i = 0; i < pile.size(); ++i) grid.add(pile.position[i]);
    dem::Particles batch;
    // Slabs one diameter thick, upward from the pile's top, each filled to the insertion fraction.
    double z0 = pile_top(s, pile) + 1.05 * r;
    for (int slab = 0; batch.size() < count; ++slab) {
        if (slab > 100000) throw std::runtime_error("pour: no room to insert spheres above the pile");
        const double lo = z0 + slab * 2 * r, hi = lo + 2 * r;
        const double reach = reach_at(s, hi);  // the narrower end of the slab
        if (reach <= 0) throw std::runtime_error("pour: the cone's top opening is narrower than a sphere");
        const double capacity = insertion_fraction * M_PI * reach * reach * 2 * r / sphere_volume(r);
        const auto want = std::min<std::size_t>(count - batch.size(), static_cast<std::size_t>(std::max(1.0, capacity)));
        for (std::size_t placed = 0, tries = 0; placed < want && tries < 200 * want; ++tries) {
            const double rho = reach * std::sqrt(unit(rng)), phi = 2 * M_PI * unit(rng);
            const dem::Vec3 x(rho * std::cos(phi), rho * std::sin(phi), lo + (hi - lo) * unit(rng));
            if (grid.any_within(x, gap)) continue;
            grid.add(x);
            batch.add(x, r, s.material.density);
            ++placed;
        }
    }
    return batch;
}

dem::Particles strike_off(const SlumpScene& s, const dem::Particles& pile) {
    dem::Particles kept;
    for (std::size_t i = 0; i < pile.size(); ++i) {
        const auto& x = pile.position[i];
        const double r = pile.radius[i];
        if (x.z() + r > s.fill_height_m || std::hypot(x.x(), x.y()) + r > cone_radius_at(s, std::max(x.z(), 0.0)) + 1e-9 * r)
            continue;
        const auto j = kept.add(x, r, s.material.density, pile.velocity[i], pile.species[i]);
        kept.angular_velocity[j] = pile.angular_velocity[i];
    }
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
    return strike_off(s, pile);
}

}  // namespace demscale::slump
