// Finished slump runs kept on disk, keyed by a hash of everything that determines the result (the
// whole scene, the tool's version and this cache's format), so sweeps resume and reports rebuild
// without rerunning: DIR/<key>.json (measures, profile, history, wall time) and DIR/<key>.csv
// (final particle state). Both are written atomically; a half-written entry never exists.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "slump/slump_run.hpp"
#include "slump/slump_scene.hpp"

namespace demscale::slump {

// 16 hex digits: FNV-1a 64 of the scene's text (slump/scene_text.hpp; name and source path excluded).
std::string scene_key(const SlumpScene& s, std::span<const dem::LawPart> parts = dem::law_parts());

class RunCache {
public:
    explicit RunCache(std::filesystem::path dir) : dir_(std::move(dir)) {}
    // nullopt when absent or unreadable (a stale format counts as absent).
    std::optional<SlumpResult> load(const std::string& key) const;
    void store(const std::string& key, const SlumpResult& r, int threads) const;
    // A run whose fill the cone could not hold (FillShortfall): DIR/<key>.unusable holds the reason,
    // so that a later call reports it without pouring again. nullopt when absent or stale.
    std::optional<std::string> load_unusable(const std::string& key) const;
    void store_unusable(const std::string& key, const std::string& reason) const;
    const std::filesystem::path& dir() const { return dir_; }

private:
    std::filesystem::path dir_;
};

}  // namespace demscale::slump
