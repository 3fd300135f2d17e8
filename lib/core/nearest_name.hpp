// "Did you mean …?": the candidate with the smallest edit distance to a mistyped name.
#pragma once

#include <span>
#include <string_view>

namespace demscale {

std::size_t edit_distance(std::string_view a, std::string_view b);
std::string_view nearest_name(std::string_view typed, std::span<const std::string_view> candidates);

}  // namespace demscale
