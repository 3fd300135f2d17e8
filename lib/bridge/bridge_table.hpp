// The exact (Young–Laplace) bridge tabulated and interpolated: the "accurate but still fast" model.
// Grid: ln V̂ uniform, θ uniform, and t uniform with ĥ/ĥ_c = (1 − cos πt)/2, which clusters nodes at
// contact (F̂ falls fast there at small V̂) and at rupture, where F̂ has a square-root singularity in
// the gap (the constant-volume family folds there). Interpolation: tricubic Catmull–Rom in ln F̂
// (C¹, so DEM forces are continuous with continuous slopes); ln ĥ_c the same way in (ln V̂, θ).
// Stored as CSV under data/.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/contact_angle.hpp"

namespace demscale::bridge {

struct BridgeTableGrid {
    double vhat_min = 1e-5, vhat_max = 0.3;
    int vhat_points = 16;
    double theta_max_deg = 40;  // the exact solver's concave scope ends near 50 deg at V^ = 0.3
    int theta_points = 5;
    int gap_points = 25;
};

class BridgeTable {
public:
    // Solves the Young–Laplace problem at every node (tens of seconds); progress(done, total).
    // Throws std::runtime_error naming the node where the solver fails.
    static BridgeTable generate(const BridgeTableGrid& grid, const std::function<void(int, int)>& progress = {});
    // Throws InputError for a missing or ill-formed file.
    static BridgeTable load(const std::string& path);
    std::string to_csv() const;

    const BridgeTableGrid& grid() const { return grid_; }
    bool covers(double vhat, ContactAngle theta) const;
    // Throw InputError outside the tabulated (V̂, θ) range.
    double hhat_rupture(double vhat, ContactAngle theta) const;
    double fhat(double vhat, ContactAngle theta, double hhat) const;  // F/(2πRγ)

    // One pair type: the (V̂, θ) interpolation done once, leaving a 1-D cubic in the gap per call.
    struct Pair {
        double hhat_rupture = 0;
        std::vector<double> column;  // F̂ at the gap nodes
        double fhat(double hhat) const;
    };
    Pair prepare(double vhat, ContactAngle theta) const;

private:
    BridgeTableGrid grid_;
    std::vector<double> fhat_;     // [v][θ][t]
    std::vector<double> ln_hc_;    // [v][θ]
    double at(int iv, int it, int ix) const;
    void locate(double vhat, ContactAngle theta, double& sv, double& st) const;
    template <class Node>
    double across_pairs(double vhat, ContactAngle theta, Node node) const;
};

}  // namespace demscale::bridge
