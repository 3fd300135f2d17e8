#include "report/caveats.hpp"

#include <cctype>

namespace demscale::report {

namespace {
struct Kind {
    std::string text;  // the message, its varying number replaced by N
    bool numbered = false;
    std::vector<std::string> entries;
};

// The first number outside parentheses: {position, length}; length 0 when none.
std::pair<std::size_t, std::size_t> first_number(const std::string& s) {
    int depth = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        if (c == '(') ++depth;
        else if (c == ')') --depth;
        else if (depth == 0 && std::isdigit(static_cast<unsigned char>(c)) &&
                 (i == 0 || !std::isalnum(static_cast<unsigned char>(s[i - 1])))) {
            std::size_t j = i;
            while (j < s.size() && (std::isdigit(static_cast<unsigned char>(s[j])) || s[j] == '.' || s[j] == 'e')) ++j;
            if (j < s.size() && std::isalpha(static_cast<unsigned char>(s[j]))) continue;  // part of a word
            return {i, j - i};
        }
    }
    return {0, 0};
}
}  // namespace

std::vector<std::string> grouped_caveats(const std::vector<Caveat>& caveats) {
    std::vector<Kind> kinds;
    for (const auto& c : caveats) {
        const auto [at, length] = first_number(c.message);
        Kind k;
        k.numbered = length > 0;
        k.text = k.numbered ? c.message.substr(0, at) + "N" + c.message.substr(at + length) : c.message;
        const std::string entry = k.numbered ? c.message.substr(at, length) + " (" + c.who + ")" : c.who;
        auto it = kinds.begin();
        while (it != kinds.end() && it->text != k.text) ++it;
        if (it == kinds.end()) kinds.push_back(std::move(k)), it = kinds.end() - 1;
        it->entries.push_back(entry);
    }
    std::vector<std::string> lines;
    for (const auto& k : kinds) {
        std::string list;
        for (const auto& e : k.entries) list += (list.empty() ? "" : k.numbered ? ", " : "; ") + e;
        lines.push_back(k.text + (k.numbered ? ": N = " : ": ") + list);
    }
    return lines;
}

}  // namespace demscale::report
