#include "slump/second_look.hpp"

#include <algorithm>
#include <map>

namespace demscale::slump {

namespace {

// "101-104" for a run of consecutive seeds, else "101, 103, 107".
std::string seed_list(const std::vector<unsigned>& seeds) {
    if (seeds.empty()) return "";
    if (seeds.back() - seeds.front() + 1 == seeds.size())
        return seeds.size() == 1 ? std::to_string(seeds.front()) : std::to_string(seeds.front()) + "-" + std::to_string(seeds.back());
    std::string out;
    for (unsigned s : seeds) out += (out.empty() ? "" : ", ") + std::to_string(s);
    return out;
}

}  // namespace

std::string SecondLook::describe() const {
    if (!any()) return "";
    const auto seeds = [](const std::vector<unsigned>& s) { return (s.size() == 1 ? "seed " : "seeds ") + seed_list(s); };
    return "SECOND LOOK: every run of " + seeds(earlier) + " came from the cache, " + seeds(added) + (added.size() == 1 ? " is" : " are") +
           " new; if the earlier result led to this call, its 95 % intervals are not exact (optional stopping, docs/verdicts.md)";
}

SecondLook second_look(const std::vector<StudyRun*>& runs) {
    std::map<unsigned, std::pair<std::size_t, std::size_t>> per_seed;  // seed → (cached, all)
    for (const auto* r : runs) {
        auto& [cached, all] = per_seed[r->scene.seed];
        cached += r->from_cache, all++;
    }
    SecondLook look;
    for (const auto& [seed, count] : per_seed) {
        if (count.first == count.second) look.earlier.push_back(seed);
        else if (count.first == 0) look.added.push_back(seed);
        else return {};  // a seed partly cached: a resumed or widened study, not more seeds
    }
    return look;
}

}  // namespace demscale::slump
