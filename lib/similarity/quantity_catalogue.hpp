// Every quantity a DEM scene uses, with its SI unit and its dimension in the (L, ρ, T) basis.
// Mass = ρL³, force = ρL⁴T⁻², stress = ρL²T⁻², etc. (Feng & Owen 2014; docs/model.md §4).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "similarity/dimension.hpp"

namespace demscale::similarity {

struct Quantity {
    std::string_view key;      // snake_case identifier used on the command line and in files
    std::string_view name;     // what a person reads
    std::string_view si_unit;
    Dimension dimension;
};

std::span<const Quantity> quantity_catalogue();

// Throws InputError naming `field` and listing the nearest key when `key` is unknown.
const Quantity& find_quantity(std::string_view key, const std::string& field);

// The catalogue key closest to `key` (edit distance), for "did you mean" messages.
std::string_view nearest_quantity_key(std::string_view key);

}  // namespace demscale::similarity
