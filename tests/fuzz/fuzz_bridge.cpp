// Fuzz target: the bridge functions at any (V̂, θ, ĥ), finite or not, read as raw doubles. Each
// model either refuses with InputError or returns a finite, non-negative force and rupture
// distance; the force is zero beyond rupture. The exact solver (milliseconds per call) is tried on
// one input in sixteen.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <memory>
#include <string>
#include <vector>

#include "bridge/bridge_model.hpp"
#include "bridge/mikami.hpp"
#include "core/input_error.hpp"
#include "io/bridge_table_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace demscale;
    if (size < 3 * sizeof(double) + 1) return 0;
    double v[3];
    std::memcpy(v, data + 1, sizeof v);
    const double vhat = v[0], theta_deg = v[1], hhat = v[2];
    // Built once: the table model reads its file, and models keep per-pair coefficients.
    static const auto models = [] {
        static const auto table = io::read_bridge_table(DEMSCALE_SOURCE_DIR "/data/bridge_table.csv");
        std::vector<std::unique_ptr<bridge::BridgeModel>> m;
        for (auto name : bridge::bridge_model_names()) m.push_back(bridge::make_bridge_model(name, &table));
        return m;
    }();
    for (const auto& model : models) {
        const std::string_view name = model->name();
        if (name == "exact" && data[0] % 16 != 0) continue;
        try {
            const ContactAngle theta{Degrees{theta_deg}};
            const double rupture = model->hhat_rupture(vhat, theta);
            const double f = model->fhat(vhat, theta, hhat);
            if (!std::isfinite(rupture) || rupture < 0) throw std::logic_error(std::string(name) + ": rupture not finite or negative");
            if (!std::isfinite(f) || f < 0) throw std::logic_error(std::string(name) + ": force not finite or negative");
            if (hhat > rupture && f != 0) throw std::logic_error(std::string(name) + ": force beyond rupture");
        } catch (const InputError&) {
            // refused with a message: fine
        }
    }
    try {  // the DEM hot path's own coefficients
        const auto k = bridge::mikami_coefficients(vhat, ContactAngle{Degrees{theta_deg}});
        const auto e = bridge::evaluate_mikami(k, hhat);
        if (!std::isfinite(e.fhat) || e.fhat < 0) throw std::logic_error("mikami: force not finite or negative");
    } catch (const InputError&) {
    }
    return 0;
}
