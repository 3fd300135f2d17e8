#include "slump/scene_text.hpp"

#include <cstdio>
#include <functional>
#include <map>
#include <sstream>
#include <vector>

#include "bridge/curve_sources.hpp"
#include "core/input_error.hpp"
#include "core/version.hpp"

namespace demscale::slump {

namespace {

// One line of the text: its name, the scene's value, whether this scene writes it, and how a
// scene read back takes the value.
struct Line {
    std::string name;
    double value;
    bool written;
    std::function<void(SlumpScene&, double)> set;
};

template <class T>
std::function<void(SlumpScene&, double)> into(T SlumpScene::*field) {
    return [field](SlumpScene& s, double v) { s.*field = static_cast<T>(v); };
}
template <class Enum>
Enum as(double v) { return static_cast<Enum>(static_cast<int>(v)); }

std::vector<Line> lines(const SlumpScene& s, std::span<const dem::LawPart> parts) {
    std::vector<Line> l = {
        {"bottom", s.bottom_diameter_m, true, into(&SlumpScene::bottom_diameter_m)},
        {"top", s.top_diameter_m, true, into(&SlumpScene::top_diameter_m)},
        {"height", s.height_m, true, into(&SlumpScene::height_m)},
        {"lift_speed", s.lift_speed_m_per_s, true, into(&SlumpScene::lift_speed_m_per_s)},
        {"lift_height", s.lift_height_m, true, into(&SlumpScene::lift_height_m)},
        {"radius", s.radius_m, true, into(&SlumpScene::radius_m)},
        {"sizes_sd", s.sizes.geometric_sd, s.sizes.lognormal(), [](SlumpScene& t, double v) { t.sizes.geometric_sd = v; }},
        {"sizes_lower_q", s.sizes.lower_quantile, s.sizes.lognormal(), [](SlumpScene& t, double v) { t.sizes.lower_quantile = v; }},
        {"sizes_upper_q", s.sizes.upper_quantile, s.sizes.lognormal(), [](SlumpScene& t, double v) { t.sizes.upper_quantile = v; }},
        {"fill", s.fill_height_m, true, into(&SlumpScene::fill_height_m)},
        {"fill_solid_fraction", s.fill_solid_fraction, true, into(&SlumpScene::fill_solid_fraction)},
        {"seed", static_cast<double>(s.seed), true, into(&SlumpScene::seed)},
        {"density", s.material.density, true, [](SlumpScene& t, double v) { t.material.density = v; }},
        {"rough_floor", s.rough_floor_diameter_m, s.rough_floor,
         [](SlumpScene& t, double v) { t.rough_floor = true, t.rough_floor_diameter_m = v; }},
        {"rolling", static_cast<double>(s.rolling_resistance), true, [](SlumpScene& t, double v) { t.rolling_resistance = v != 0; }},
        {"rolling_model", static_cast<double>(s.rolling_model), true,
         [](SlumpScene& t, double v) { t.rolling_model = as<dem::RollingModel>(v); }},
        {"wet", static_cast<double>(s.wet), true, [](SlumpScene& t, double v) { t.wet = v != 0; }},
        {"wet_walls", static_cast<double>(s.wet_walls), true, [](SlumpScene& t, double v) { t.wet_walls = v != 0; }},
        {"variant", static_cast<double>(s.bridge.variant), s.wet,
         [](SlumpScene& t, double v) { t.bridge.variant = as<bridge::MikamiVariant>(v); }},
        {"rupture", static_cast<double>(s.bridge.rupture), s.wet,
         [](SlumpScene& t, double v) { t.bridge.rupture = as<bridge::RuptureLaw>(v); }},
    };
    // A sieve table's classes: radius / R and mass fraction, written for the classes it has (one
    // radius and the lognormal write none, so their keys stay as they were).
    for (std::size_t c = 0; c < max_size_classes; ++c) {
        const bool given = c < s.sizes.class_ratios.size() && s.sizes.sieve();
        auto grow = [c](SlumpScene& t) {
            if (t.sizes.class_ratios.size() <= c) t.sizes.class_ratios.resize(c + 1), t.sizes.mass_fractions.resize(c + 1);
        };
        l.push_back({"size_class_" + std::to_string(c), given ? s.sizes.class_ratios[c] : 0, given,
                     [grow, c](SlumpScene& t, double v) { grow(t), t.sizes.class_ratios[c] = v; }});
        l.push_back({"size_mass_" + std::to_string(c), given ? s.sizes.mass_fractions[c] : 0, given,
                     [grow, c](SlumpScene& t, double v) { grow(t), t.sizes.mass_fractions[c] = v; }});
    }
    // Each bridge curve source other than the fit has its line (bridge/curve_sources.hpp; the exact
    // curves came after format 5), written only where it acts, so that the keys of fitted scenes
    // stayed as they were. Absent means the fit.
    auto curve_lines = [&](bridge::BridgeGeometry geometry, bool acts, bridge::CurveSource SlumpScene::*field, const char* prefix) {
        for (const auto& source : bridge::curve_sources())
            if (!source.cache_name.empty() && source.has(geometry))
                l.push_back({prefix + std::string(source.cache_name), 1, acts && s.*field == source.source,
                             [field, chosen = source.source](SlumpScene& t, double) { t.*field = chosen; }});
    };
    curve_lines(bridge::BridgeGeometry::sphere_sphere, s.wet, &SlumpScene::particle_curve, "particle_curve_");
    l.push_back({"lubrication", static_cast<double>(s.lubrication), s.wet && s.viscosity_pa_s > 0,
                 [](SlumpScene& t, double v) { t.lubrication = as<dem::Lubrication>(v); }});
    curve_lines(bridge::BridgeGeometry::sphere_wall, s.wet && s.wet_walls, &SlumpScene::wall_curve, "wall_curve_");
    // A law a slot key chose, other than the slot's first (default) part, has its line, law_CHOICE,
    // written where it acts: scenes with the default laws keep their keys. (The other slots' laws
    // follow from keys that have lines of their own: wet, rolling_model, SJKR's k_c.)
    for (const auto& part : parts)
        if (!part.choice.empty() && !dem::slot_key(part.slot).empty() && &part != &dem::default_part(part.slot, parts))
            l.push_back({"law_" + std::string(part.choice), 1, part.active(s), [choose = part.choose](SlumpScene& t, double) { choose(t); }});
    for (const auto& part : parts)
        for (const auto& p : part.parameters)
            l.push_back({std::string(p.key), p.get(s), part.active(s), [set = p.set](SlumpScene& t, double v) { set(t, v); }});
    const std::vector<Line> protocol = {
        {"dt", s.dt_s, true, into(&SlumpScene::dt_s)},
        {"g", s.gravity, true, into(&SlumpScene::gravity)},
        {"settle", s.settle_time_s, true, into(&SlumpScene::settle_time_s)},
        {"spread", s.spread_time_s, true, into(&SlumpScene::spread_time_s)},
        {"rest_speed", s.rest_speed_m_per_s, true, into(&SlumpScene::rest_speed_m_per_s)},
        {"rest_duration", s.rest_duration_s, true, into(&SlumpScene::rest_duration_s)},
        {"skin", s.skin_m, true, into(&SlumpScene::skin_m)},
        {"fill_kind", static_cast<double>(s.fill), true, [](SlumpScene& t, double v) { t.fill = as<FillKind>(v); }},
        {"pour_time", s.pour_time_s, true, into(&SlumpScene::pour_time_s)},
        {"rest_quantile", s.rest_quantile, true, into(&SlumpScene::rest_quantile)},
        {"liggghts_ranks", static_cast<double>(s.liggghts_ranks), s.liggghts_ranks > 0, into(&SlumpScene::liggghts_ranks)},
    };
    l.insert(l.end(), protocol.begin(), protocol.end());
    return l;
}

std::string header() { return std::string("demscale=") + version + "\ncache=" + std::to_string(cache_format) + "\n"; }

}  // namespace

std::string scene_text(const SlumpScene& s, std::span<const dem::LawPart> parts) {
    std::string t = header();
    for (const auto& line : lines(s, parts)) {
        if (!line.written) continue;
        char b[160];
        std::snprintf(b, sizeof b, "%.*s=%.17g\n", static_cast<int>(line.name.size()), line.name.data(), line.value);
        t += b;
    }
    return t;
}

SlumpScene scene_from_text(const std::string& text, const std::string& source, std::span<const dem::LawPart> parts) {
    SlumpScene s;
    s.name = source, s.source = source;
    s.particle_curve = s.wall_curve = bridge::CurveSource::fit;  // an exact curve has its own line
    std::map<std::string, std::function<void(SlumpScene&, double)>> setters;
    for (auto& line : lines(s, parts)) setters.emplace(line.name, std::move(line.set));
    std::istringstream in(text);
    std::string line, body;
    for (int n = 1; std::getline(in, line); ++n) {
        if (line.empty() || line[0] == '#') continue;
        body += line + "\n";
        const std::string where = source + ":" + std::to_string(n);
        const auto eq = line.find('=');
        if (eq == std::string::npos) throw InputError(where, line, "NAME=VALUE lines as demscale writes a scene's text");
        const std::string name = line.substr(0, eq), value = line.substr(eq + 1);
        if (name == "demscale" || name == "cache") {
            const std::string ours = name == "demscale" ? std::string(version) : std::to_string(cache_format);
            if (value != ours)
                throw InputError(where, line, "a scene written by this demscale (" + name + "=" + ours + "): run it with the same build");
            continue;
        }
        const auto set = setters.find(name);
        if (set == setters.end()) throw InputError(where, name, "a line name demscale writes (bottom, radius, seed, ...)");
        char* end = nullptr;
        const double v = std::strtod(value.c_str(), &end);
        if (value.empty() || end != value.c_str() + value.size()) throw InputError(where, line, "NAME=NUMBER");
        set->second(s, v);
    }
    if (scene_text(s, parts) != body)
        throw InputError(source, "(the whole text)", "lines in the order and with the values demscale writes; this one reads back as another scene");
    return s;
}

}  // namespace demscale::slump
