#include "bridge/bridge_model.hpp"

#include <array>
#include <cmath>
#include <optional>

#include "bridge/bridge_table.hpp"
#include "bridge/closed_forms.hpp"
#include "bridge/mikami.hpp"
#include "bridge/young_laplace.hpp"
#include "core/input_error.hpp"
#include "core/nearest_name.hpp"

namespace demscale::bridge {

namespace {

constexpr std::array<std::string_view, 7> names{"exact", "mikami1998", "yun-park-2017", "willett", "willett-simple",
                                                "toroidal", "table"};

// Remembers what a model prepared for the last (V̂, θ): one DEM pair type pays setup once.
template <class Prepared>
class PerPairCache {
public:
    template <class Make>
    const Prepared& get(double vhat, ContactAngle theta, Make&& make) const {
        if (!value_ || vhat != vhat_ || theta.radians() != theta_) {
            value_.emplace(make());
            vhat_ = vhat;
            theta_ = theta.radians();
        }
        return *value_;
    }

private:
    mutable std::optional<Prepared> value_;
    mutable double vhat_ = 0, theta_ = 0;
};

class MikamiModel final : public BridgeModel {
public:
    explicit MikamiModel(MikamiVariant v) : options_{v, RuptureLaw::mikami1998} {}
    std::string_view name() const override { return to_string(options_.variant); }
    double hhat_rupture(double vhat, ContactAngle theta) const override { return coefficients(vhat, theta).hhat_rupture; }
    double fhat(double vhat, ContactAngle theta, double hhat) const override {
        const auto& k = coefficients(vhat, theta);
        return f_over_2pi_r_gamma(k, mikami_fhat(k, hhat));
    }
    FittedRange fitted_range() const override {
        const ValidityRange r;
        return {r.vhat_min, r.vhat_max, r.theta_max_deg,
                "the range commonly quoted for this class of fits; Mikami et al. (1998)'s own statement not consulted (docs/model.md)"};
    }
    std::optional<ValidityWarning> finding(double vhat, ContactAngle theta, double hhat) const override {
        return clamped_at(coefficients(vhat, theta), hhat);
    }

private:
    const MikamiCoefficients& coefficients(double vhat, ContactAngle theta) const {
        return cache_.get(vhat, theta, [&] { return mikami_coefficients(vhat, theta, options_); });
    }
    MikamiOptions options_;
    PerPairCache<MikamiCoefficients> cache_;
};

class ExactModel final : public BridgeModel {
public:
    std::string_view name() const override { return "exact"; }
    double hhat_rupture(double vhat, ContactAngle theta) const override {
        checked(vhat, theta, family(vhat, theta).solve(0.0));
        return family(vhat, theta).hhat_rupture();
    }
    double fhat(double vhat, ContactAngle theta, double hhat) const override {
        const auto r = checked(vhat, theta, family(vhat, theta).solve(std::max(hhat, 0.0)));
        return r.status == YoungLaplaceStatus::above_rupture ? 0.0 : r.shape.fhat_neck;
    }
    FittedRange fitted_range() const override {
        return {0, std::numeric_limits<double>::infinity(), 90, "no fit: concave bridges, refused with a message elsewhere"};
    }

private:
    // Out of scope is the input's doing (InputError, exit 2); not converging is the solver's.
    static const YoungLaplaceResult& checked(double vhat, ContactAngle theta, const YoungLaplaceResult& r) {
        if (r.status == YoungLaplaceStatus::outside_scope)
            throw InputError("vhat, theta", format_number(vhat) + ", " + format_number(theta.degrees()) + " deg",
                             "a concave (pendular) bridge, the exact solver's scope (" + r.message + ")");
        if (r.status == YoungLaplaceStatus::not_converged) throw std::runtime_error("exact bridge: " + r.message);
        return r;
    }
    const YoungLaplaceBridge& family(double vhat, ContactAngle theta) const {
        return cache_.get(vhat, theta, [&] { return YoungLaplaceBridge(vhat, theta); });
    }
    PerPairCache<YoungLaplaceBridge> cache_;
};

class WillettModel final : public BridgeModel {
public:
    explicit WillettModel(bool full) : full_(full) {}
    std::string_view name() const override { return full_ ? "willett" : "willett-simple"; }
    double hhat_rupture(double vhat, ContactAngle theta) const override {
        in_range(vhat);
        return willett_rupture_hhat(vhat, theta);
    }
    double fhat(double vhat, ContactAngle theta, double hhat) const override {
        if (hhat > hhat_rupture(vhat, theta)) return 0.0;
        const double f = full_ ? willett_full_fhat(vhat, theta, hhat) : willett_simple_fhat(vhat, theta, hhat);
        if (!std::isfinite(f))  // the fit's polynomials in ln V̂ overflow: refuse rather than return inf/NaN
            throw InputError("vhat, theta, hhat", format_number(vhat) + ", " + format_number(theta.degrees()) + ", " + format_number(hhat),
                             "values where Willett et al.'s fit is finite");
        return f;
    }
    FittedRange fitted_range() const override {
        return {1e-6, 1.0, 90,
                "Willett et al. (2000)'s fitted range not consulted; demscale evaluates V^ in [1e-6, 1], where the fit stays finite",
                false};
    }

private:
    // Pendular-bridge fits: cubic polynomials in ln V̂ that overflow far outside the volumes fitted
    // (found by fuzzing: V̂ = 5e303 gave inf). Fuzz corpus: tests/fuzz/corpus/bridge/willett-overflow.
    static void in_range(double vhat) {
        if (!(vhat >= 1e-6 && vhat <= 1.0)) throw InputError("vhat", format_number(vhat), "[1e-06, 1] for Willett et al.'s fits");
    }
    bool full_;
};

class ToroidalModel final : public BridgeModel {
public:
    std::string_view name() const override { return "toroidal"; }
    double hhat_rupture(double vhat, ContactAngle theta) const override { return rupture_hhat(vhat, theta, RuptureLaw::lian1993); }
    double fhat(double vhat, ContactAngle theta, double hhat) const override {
        if (hhat > hhat_rupture(vhat, theta)) return 0.0;
        return toroidal_bridge(vhat, theta, hhat).fhat;
    }
    FittedRange fitted_range() const override {
        return {0, std::numeric_limits<double>::infinity(), 90, "an approximation (circle meridian), not a fit: no range", false};
    }
    std::optional<ValidityWarning> finding(double vhat, ContactAngle theta, double hhat) const override {
        if (hhat > hhat_rupture(vhat, theta) || toroidal_bridge(vhat, theta, hhat).fhat > 0) return std::nullopt;
        throw InputError("vhat, theta, hhat", format_number(vhat) + ", " + format_number(theta.degrees()) + " deg, " + format_number(hhat),
                         "a bridge the toroidal model can shape (no circle meridian holds this volume at this gap and contact angle)");
    }
};

class TableModel final : public BridgeModel {
public:
    explicit TableModel(BridgeTable t) : table_(std::move(t)) {}
    std::string_view name() const override { return "table"; }
    double hhat_rupture(double vhat, ContactAngle theta) const override { return pair(vhat, theta).hhat_rupture; }
    double fhat(double vhat, ContactAngle theta, double hhat) const override { return pair(vhat, theta).fhat(hhat); }
    FittedRange fitted_range() const override {
        const auto& g = table_.grid();
        return {g.vhat_min, g.vhat_max, g.theta_max_deg, "the tabulated grid (data/bridge_table.csv); it refuses inputs outside"};
    }

private:
    const BridgeTable::Pair& pair(double vhat, ContactAngle theta) const {
        return cache_.get(vhat, theta, [&] { return table_.prepare(vhat, theta); });
    }
    BridgeTable table_;
    PerPairCache<BridgeTable::Pair> cache_;
};

}  // namespace

std::span<const std::string_view> bridge_model_names() { return names; }

ModelEvaluation evaluate(const BridgeModel& model, double vhat, ContactAngle theta, double hhat) {
    ModelEvaluation e;
    e.hhat_rupture = model.hhat_rupture(vhat, theta);
    e.fhat = model.fhat(vhat, theta, hhat);
    e.bridge_exists = hhat <= e.hhat_rupture && e.fhat > 0;
    const auto range = model.fitted_range();
    if (range.stated && (vhat < range.vhat_min || vhat > range.vhat_max || theta.degrees() > range.theta_max_deg))
        e.flags.push_back({"outside_fitted_range", std::string(model.name()) + " is fitted for V^ in [" + format_number(range.vhat_min) +
                                                       ", " + format_number(range.vhat_max) + "], theta <= " +
                                                       format_number(range.theta_max_deg) + " deg (" + range.source + ")"});
    const double bound = std::cos(theta.radians());
    if (e.fhat > bound * (1 + 1e-12))
        e.flags.push_back({"above_physical_bound", "F/(2 pi R gamma) = " + format_short(e.fhat, 4) + " exceeds cos theta = " +
                                                       format_short(bound, 4) + ", the small-volume limit at contact"});
    if (auto f = model.finding(vhat, theta, hhat)) e.flags.push_back(*f);
    return e;
}

std::unique_ptr<BridgeModel> make_bridge_model(std::string_view name, const BridgeTable* table) {
    if (name == "exact") return std::make_unique<ExactModel>();
    if (name == "mikami1998") return std::make_unique<MikamiModel>(MikamiVariant::mikami1998);
    if (name == "yun-park-2017") return std::make_unique<MikamiModel>(MikamiVariant::yun_park_2017);
    if (name == "willett") return std::make_unique<WillettModel>(true);
    if (name == "willett-simple") return std::make_unique<WillettModel>(false);
    if (name == "toroidal") return std::make_unique<ToroidalModel>();
    if (name == "table") {
        if (!table) throw InputError("--table", "(none)", "a tabulated bridge (demscale bridge-table writes one)");
        return std::make_unique<TableModel>(*table);
    }
    std::string all;
    for (auto n : names) all += (all.empty() ? "" : ", ") + std::string(n);
    throw InputError("--model", "\"" + std::string(name) + "\"",
                     "one of " + all + " (did you mean " + std::string(nearest_name(name, names)) + "?)");
}

}  // namespace demscale::bridge
