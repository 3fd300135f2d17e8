// The report's caveats, one line per kind: the same warning raised by many runs or ensembles
// ("top opening 3.1 diameters wide (< 5)" at every coarse S_f) is printed once, listing whom it
// affects and each one's value.
#pragma once

#include <string>
#include <vector>

namespace demscale::report {

struct Caveat {
    std::string who;      // "fine", "S_f = 1.4, k = 1", "bridge model", ...
    std::string message;  // "top opening 3.1 diameters wide (< 5)"
};

// Caveats whose messages differ only in their first number outside parentheses are one kind:
// "top opening N diameters wide (< 5): N = 4.3 (fine), 3.1 (S_f = 1.4, k = 1)". Others are
// grouped when their messages are equal: "runs not at rest: fine; S_f = 1.4, k = 3". Kinds keep
// the order of their first appearance.
std::vector<std::string> grouped_caveats(const std::vector<Caveat>& caveats);

}  // namespace demscale::report
