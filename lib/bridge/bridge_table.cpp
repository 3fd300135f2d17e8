#include "bridge/bridge_table.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "bridge/young_laplace.hpp"
#include "core/input_error.hpp"

namespace demscale::bridge {

namespace {

// Catmull–Rom through p[0..3] at nodes −1, 0, 1, 2, evaluated at f ∈ [0, 1].
double catmull_rom(const double p[4], double f) {
    return p[1] + 0.5 * f * (p[2] - p[0] + f * (2 * p[0] - 5 * p[1] + 4 * p[2] - p[3] + f * (3 * (p[1] - p[2]) + p[3] - p[0])));
}

// Four nodes around s ∈ [0, n−1] and the fraction.
void stencil(double s, int n, int& i0, double& f) {
    i0 = std::clamp(static_cast<int>(std::floor(s)), 0, n - 2);
    f = s - i0;
}

// Outside nodes extrapolate linearly, or mirror where the function is even about the end node:
// in the gap coordinate at contact (ĥ ∝ t²), and at a rupture without a fold (ĥ_c − ĥ ∝ (1 − t)²).
template <class Get>
double cubic_1d(Get get, int n, int i0, double f, bool even_at_start = false, bool even_at_end = false) {
    double p[4];
    for (int k = -1; k <= 2; ++k) {
        const int i = i0 + k;
        p[k + 1] = i < 0    ? (even_at_start ? get(1) : 2 * get(0) - get(1))
                   : i >= n ? (even_at_end ? get(n - 2) : 2 * get(n - 1) - get(n - 2))
                            : get(i);
    }
    return catmull_rom(p, f);
}

}  // namespace

// Nodes cluster at contact (fast decay at small V̂) and at rupture, where 1 − x ∝ (1 − t)² turns the
// square-root fold into a smooth function of t.
double BridgeTable::gap_fraction(double t) { return 0.5 * (1.0 - std::cos(std::numbers::pi * t)); }
double BridgeTable::gap_coordinate(double x) { return std::acos(1.0 - 2.0 * x) / std::numbers::pi; }

double BridgeTable::at(int iv, int it, int ix) const {
    return fhat_[(static_cast<std::size_t>(iv) * grid_.theta_points + it) * grid_.gap_points + ix];
}

BridgeTable BridgeTable::generate(const BridgeTableGrid& g, const std::function<void(int, int)>& progress) {
    BridgeTable table;
    table.grid_ = g;
    table.fhat_.resize(static_cast<std::size_t>(g.vhat_points) * g.theta_points * g.gap_points);
    table.ln_hc_.resize(static_cast<std::size_t>(g.vhat_points) * g.theta_points);
    const int total = g.vhat_points * g.theta_points;
    for (int iv = 0; iv < g.vhat_points; ++iv) {
        const double vhat = std::exp(std::log(g.vhat_min) + (std::log(g.vhat_max) - std::log(g.vhat_min)) * iv / (g.vhat_points - 1));
        for (int it = 0; it < g.theta_points; ++it) {
            const ContactAngle theta{Degrees{g.theta_max_deg * it / (g.theta_points - 1)}};
            Pair column;
            try {
                column = solve_column(YoungLaplaceBridge(vhat, theta), g.gap_points);
            } catch (const std::runtime_error& e) {
                throw std::runtime_error("table node V^ = " + format_number(vhat) + ", theta = " + format_number(theta.degrees()) +
                                         " deg, " + e.what());
            }
            table.ln_hc_[iv * g.theta_points + it] = std::log(column.hhat_rupture);
            std::copy(column.column.begin(), column.column.end(),
                      table.fhat_.begin() + (static_cast<std::ptrdiff_t>(iv) * g.theta_points + it) * g.gap_points);
            if (progress) progress(iv * g.theta_points + it + 1, total);
        }
    }
    return table;
}

BridgeTable::Pair BridgeTable::solve_column(const YoungLaplaceBridge& bridge, int gap_points) {
    if (!bridge.family_ok()) throw std::runtime_error(bridge.family_message());
    Pair p;
    p.hhat_rupture = bridge.hhat_rupture();
    p.even_at_rupture = bridge.rupture_has_slope();
    for (int ix = 0; ix < gap_points; ++ix) {
        const double x = gap_fraction(double(ix) / (gap_points - 1));
        const auto r = bridge.solve(x * p.hhat_rupture);
        if (!r.ok()) throw std::runtime_error("gap node h^/h^_c = " + format_number(x) + ": " + r.message);
        p.column.push_back(std::log(r.shape.fhat_neck));  // interpolated in ln F^, as the table
    }
    return p;
}

double BridgeTable::node_vhat(int iv) const {
    const auto& g = grid_;
    return std::exp(std::log(g.vhat_min) + (std::log(g.vhat_max) - std::log(g.vhat_min)) * iv / (g.vhat_points - 1));
}
double BridgeTable::node_theta_deg(int it) const { return grid_.theta_max_deg * it / (grid_.theta_points - 1); }
double BridgeTable::node_gap_fraction(int ix) const { return gap_fraction(double(ix) / (grid_.gap_points - 1)); }
double BridgeTable::node_hhat_rupture(int iv, int it) const { return std::exp(ln_hc_[iv * grid_.theta_points + it]); }
double BridgeTable::node_fhat(int iv, int it, int ix) const { return std::exp(at(iv, it, ix)); }

BridgeTable BridgeTable::from_nodes(const BridgeTableGrid& g, const std::vector<double>& fhat, const std::vector<double>& hhat_rupture) {
    const std::size_t pairs = static_cast<std::size_t>(g.vhat_points) * g.theta_points;
    if (g.vhat_points < 2 || g.theta_points < 2 || g.gap_points < 2 || !(g.vhat_min > 0) || !(g.vhat_max > g.vhat_min) ||
        fhat.size() != pairs * g.gap_points || hhat_rupture.size() != pairs)
        throw std::invalid_argument("bridge table: grid and node counts do not agree");
    BridgeTable t;
    t.grid_ = g;
    for (double f : fhat) {
        if (!(std::isfinite(f) && f > 0)) throw std::invalid_argument("bridge table: F^ not finite and > 0");
        t.fhat_.push_back(std::log(f));  // interpolated in ln F^: its variation is multiplicative
    }
    for (double hc : hhat_rupture) {
        if (!(std::isfinite(hc) && hc > 0)) throw std::invalid_argument("bridge table: h^_c not finite and > 0");
        t.ln_hc_.push_back(std::log(hc));
    }
    return t;
}

bool BridgeTable::covers(double vhat, ContactAngle theta) const {
    return vhat >= grid_.vhat_min * (1 - 1e-12) && vhat <= grid_.vhat_max * (1 + 1e-12) &&
           theta.degrees() <= grid_.theta_max_deg + 1e-12;
}

void BridgeTable::locate(double vhat, ContactAngle theta, double& sv, double& st) const {
    require_positive(vhat, "vhat");
    if (!covers(vhat, theta))
        throw InputError("vhat, theta", format_number(vhat) + ", " + format_number(theta.degrees()) + " deg",
                         "the table's range V^ in [" + format_number(grid_.vhat_min) + ", " + format_number(grid_.vhat_max) +
                             "], theta <= " + format_number(grid_.theta_max_deg) + " deg (use --model exact outside it)");
    sv = std::clamp((std::log(vhat) - std::log(grid_.vhat_min)) / (std::log(grid_.vhat_max) - std::log(grid_.vhat_min)) *
                        (grid_.vhat_points - 1), 0.0, double(grid_.vhat_points - 1));
    st = std::clamp(theta.degrees() / grid_.theta_max_deg * (grid_.theta_points - 1), 0.0, double(grid_.theta_points - 1));
}

// Cubic interpolation in (ln V̂, θ) of any per-node quantity node(iv, it).
template <class Node>
double BridgeTable::across_pairs(double vhat, ContactAngle theta, Node node) const {
    double sv, st;
    locate(vhat, theta, sv, st);
    int iv, it;
    double fv, ft;
    stencil(sv, grid_.vhat_points, iv, fv);
    stencil(st, grid_.theta_points, it, ft);
    auto along_theta = [&](int v) { return cubic_1d([&](int th) { return node(v, th); }, grid_.theta_points, it, ft); };
    return cubic_1d(along_theta, grid_.vhat_points, iv, fv);
}

double BridgeTable::hhat_rupture(double vhat, ContactAngle theta) const {
    return std::exp(across_pairs(vhat, theta, [&](int v, int th) { return ln_hc_[v * grid_.theta_points + th]; }));
}

BridgeTable::Pair BridgeTable::prepare(double vhat, ContactAngle theta) const {
    Pair p;
    p.hhat_rupture = hhat_rupture(vhat, theta);
    for (int ix = 0; ix < grid_.gap_points; ++ix)
        p.column.push_back(across_pairs(vhat, theta, [&](int v, int th) { return at(v, th, ix); }));
    return p;
}

double BridgeTable::Pair::fhat(double hhat) const {
    const double x = std::max(hhat, 0.0) / hhat_rupture;
    if (x > 1.0) return 0.0;
    const int n = static_cast<int>(column.size());
    int ix;
    double fx;
    stencil(gap_coordinate(x) * (n - 1), n, ix, fx);
    return std::exp(cubic_1d([&](int k) { return column[k]; }, n, ix, fx, true, even_at_rupture));
}

double BridgeTable::fhat(double vhat, ContactAngle theta, double hhat) const { return prepare(vhat, theta).fhat(hhat); }

}  // namespace demscale::bridge
