// One interface for every liquid-bridge law between equal spheres: (V̂, θ, ĥ) → F̂ = F/(2πRγ),
// with its rupture distance. Lengths over R, ĥ = full gap / R; ĥ < 0 (overlap) counts as contact;
// beyond rupture the force is exactly 0. Models keep per-(V̂, θ) coefficients of the last call, so
// a DEM pair type pays the setup once; use one model object per thread.
#pragma once

#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "bridge/bridge_table.hpp"
#include "bridge/validity.hpp"
#include "core/contact_angle.hpp"

namespace demscale::bridge {

// Where a model's coefficients were fitted (or its table spans), and where that statement comes
// from; stated = false: no range is known to demscale (an approximation, or a paper not consulted).
struct FittedRange {
    double vhat_min = 0, vhat_max = std::numeric_limits<double>::infinity();
    double theta_max_deg = 90;
    std::string source;
    bool stated = true;
};

class BridgeModel {
public:
    virtual ~BridgeModel() = default;
    virtual std::string_view name() const = 0;
    virtual double hhat_rupture(double vhat, ContactAngle theta) const = 0;
    virtual double fhat(double vhat, ContactAngle theta, double hhat) const = 0;  // F/(2πRγ)
    virtual FittedRange fitted_range() const = 0;
    // What the force alone does not show at (V̂, θ, ĥ): "clamped" (the fit was negative and is
    // printed as 0); nullopt: nothing. Throws InputError where a closed form has no shape there.
    virtual std::optional<ValidityWarning> finding(double, ContactAngle, double) const { return std::nullopt; }
};

// One evaluation as the tools print it: the force, whether a bridge exists (inside rupture and
// pulling: a clamped fit has none), and every flag: outside_fitted_range, above_physical_bound
// (F/(2πRγ) > cos θ, the small-volume limit at contact), and the model's own finding. Throws
// InputError where the model finds no shape (an error, not a force of 0).
struct ModelEvaluation {
    double fhat = 0, hhat_rupture = 0;
    bool bridge_exists = false;
    std::vector<ValidityWarning> flags;
};
ModelEvaluation evaluate(const BridgeModel& model, double vhat, ContactAngle theta, double hhat);

// Names: exact, mikami1998, yun-park-2017, willett, willett-simple, toroidal, table.
// "table" interpolates the given tabulated exact solution (io::read_bridge_table reads one); it
// throws InputError without one. Throws InputError for other names.
std::unique_ptr<BridgeModel> make_bridge_model(std::string_view name, const BridgeTable* table = nullptr);
std::span<const std::string_view> bridge_model_names();

}  // namespace demscale::bridge
