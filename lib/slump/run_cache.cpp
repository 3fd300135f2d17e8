#include "slump/run_cache.hpp"

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/atomic_file.hpp"
#include "io/particle_state.hpp"
#include "slump/scene_text.hpp"

namespace demscale::slump {

namespace {

// One history sample as a flat array: time, height, spread, then the ledger field by field.
nlohmann::json history_row(const TimePoint& h) {
    const auto& e = h.energy;
    const auto& d = e.dissipated;
    return {h.time, h.height, h.spread_max, e.kinetic, e.gravitational, e.stored.normal, e.stored.tangential, e.stored.rolling,
            e.stored.bridge, d.normal_damping, d.friction, d.rolling, d.bridge, d.spring_stiffness, e.wall_work};
}
TimePoint history_point(const nlohmann::json& a) {
    TimePoint h{a.at(0), a.at(1), a.at(2), {}};
    auto& e = h.energy;
    auto& d = e.dissipated;
    e.kinetic = a.at(3), e.gravitational = a.at(4);
    e.stored = {a.at(5), a.at(6), a.at(7), a.at(8)};
    d = {a.at(9), a.at(10), a.at(11), a.at(12), a.at(13)};
    e.wall_work = a.at(14);
    return h;
}

}  // namespace

std::string scene_key(const SlumpScene& s, std::span<const dem::LawPart> parts) {
    std::uint64_t h = 14695981039346656037ull;
    for (unsigned char c : scene_text(s, parts)) h = (h ^ c) * 1099511628211ull;
    char b[17];
    std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(h));
    return b;
}

void RunCache::store(const std::string& key, const SlumpResult& r, int threads) const {
    nlohmann::json j;
    j["format"] = cache_format;
    j["particles"] = r.particles, j["steps"] = r.steps, j["threads"] = threads;
    j["dt"] = r.dt, j["critical_dt"] = r.critical_dt, j["wall_s"] = r.wall_s;
    j["settle_end"] = r.settle_end, j["lift_end"] = r.lift_end, j["end"] = r.end;
    j["settled"] = r.settled, j["came_to_rest"] = r.came_to_rest, j["initial_height"] = r.initial_height;
    j["height"] = r.final.height, j["spread"] = r.final.spread, j["bulk_fraction"] = r.final.bulk_fraction;
    j["height_top"] = r.final.height_top, j["spread_d95"] = r.final.spread_d95, j["spread_max"] = r.final.spread_max;
    j["foot"] = r.final.foot;
    j["repose_angle_deg"] = r.final.repose_angle_deg ? nlohmann::json(*r.final.repose_angle_deg) : nlohmann::json();
    const auto& f = r.fill;
    j["fill"] = {f.top, f.mass, f.height, f.solid_fraction, f.core_fraction, f.coordination, f.max_overlap, f.core_points};
    j["pour_time"] = r.pour_time, j["pour_steps"] = r.pour_steps, j["rest_since"] = r.rest_since;
    const auto& m = r.motion;
    j["motion"] = {m.speed_p50, m.speed_p99, m.speed_max, m.spin_p99, m.moving, m.moving_at_edge};
    for (const auto& p : r.final.profile) j["profile"].push_back({p.radius, p.height});
    for (const auto& p : r.final.profile_tops) j["profile_tops"].push_back({p.radius, p.height});
    for (const auto& h : r.history) j["history"].push_back(history_row(h));
    // The state first: an entry counts only once its JSON exists.
    io::write_particle_state(dir_ / (key + ".csv"), r.final_state);
    io::write_file_atomically(dir_ / (key + ".json"), j.dump(1) + "\n");
}

std::optional<std::string> RunCache::load_unusable(const std::string& key) const {
    std::ifstream in(dir_ / (key + ".unusable"));
    if (!in) return std::nullopt;
    try {
        const auto j = nlohmann::json::parse(in);
        if (j.at("format").get<int>() != cache_format) return std::nullopt;
        return j.at("unusable").get<std::string>();
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

void RunCache::store_unusable(const std::string& key, const std::string& reason) const {
    nlohmann::json j;
    j["format"] = cache_format;
    j["unusable"] = reason;
    io::write_file_atomically(dir_ / (key + ".unusable"), j.dump(1) + "\n");
}

std::optional<SlumpResult> RunCache::load(const std::string& key) const {
    std::ifstream in(dir_ / (key + ".json"));
    if (!in || !std::filesystem::exists(dir_ / (key + ".csv"))) return std::nullopt;
    try {
        const auto j = nlohmann::json::parse(in);
        if (j.at("format").get<int>() != cache_format) return std::nullopt;
        SlumpResult r;
        r.particles = j.at("particles"), r.steps = j.at("steps");
        r.dt = j.at("dt"), r.critical_dt = j.at("critical_dt"), r.wall_s = j.at("wall_s");
        r.settle_end = j.at("settle_end"), r.lift_end = j.at("lift_end"), r.end = j.at("end");
        r.settled = j.at("settled"), r.came_to_rest = j.at("came_to_rest"), r.initial_height = j.at("initial_height");
        r.final.height = j.at("height"), r.final.spread = j.at("spread"), r.final.bulk_fraction = j.at("bulk_fraction");
        r.final.height_top = j.at("height_top"), r.final.spread_d95 = j.at("spread_d95"), r.final.spread_max = j.at("spread_max");
        r.final.foot = j.at("foot");
        if (!j.at("repose_angle_deg").is_null()) r.final.repose_angle_deg = j.at("repose_angle_deg").get<double>();
        const auto& f = j.at("fill");
        r.fill = {f.at(0), f.at(1), f.at(2), f.at(3), f.at(4), f.at(5), f.at(6), f.at(7)};
        r.pour_time = j.at("pour_time"), r.pour_steps = j.at("pour_steps"), r.rest_since = j.at("rest_since");
        const auto& m = j.at("motion");
        r.motion = {m.at(0), m.at(1), m.at(2), m.at(3), m.at(4), m.at(5)};
        for (const auto& p : j.at("profile")) r.final.profile.push_back({p.at(0), p.at(1)});
        for (const auto& p : j.value("profile_tops", nlohmann::json::array())) r.final.profile_tops.push_back({p.at(0), p.at(1)});
        for (const auto& h : j.at("history")) r.history.push_back(history_point(h));
        r.final_state = io::read_particle_state((dir_ / (key + ".csv")).string());
        return r;
    } catch (const std::exception&) {
        return std::nullopt;  // unreadable: run again and overwrite
    }
}

}  // namespace demscale::slump
