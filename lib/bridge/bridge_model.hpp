// One interface for every liquid-bridge law between equal spheres: (V̂, θ, ĥ) → F̂ = F/(2πRγ),
// with its rupture distance. Lengths over R, ĥ = full gap / R; ĥ < 0 (overlap) counts as contact;
// beyond rupture the force is exactly 0. Models keep per-(V̂, θ) coefficients of the last call, so
// a DEM pair type pays the setup once; use one model object per thread.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "bridge/bridge_table.hpp"
#include "core/contact_angle.hpp"

namespace demscale::bridge {

class BridgeModel {
public:
    virtual ~BridgeModel() = default;
    virtual std::string_view name() const = 0;
    virtual double hhat_rupture(double vhat, ContactAngle theta) const = 0;
    virtual double fhat(double vhat, ContactAngle theta, double hhat) const = 0;  // F/(2πRγ)
};

// Names: exact, mikami1998, yun-park-2017, willett, willett-simple, toroidal, table.
// "table" interpolates the given tabulated exact solution (io::read_bridge_table reads one); it
// throws InputError without one. Throws InputError for other names.
std::unique_ptr<BridgeModel> make_bridge_model(std::string_view name, const BridgeTable* table = nullptr);
std::span<const std::string_view> bridge_model_names();

}  // namespace demscale::bridge
