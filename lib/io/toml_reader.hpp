// Strict reading of a TOML input file: every error names file, line, key, value and the accepted
// range; an unknown section or key is an error that suggests the nearest valid name (a typo in an
// input must never be silently ignored).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <toml++/toml.h>
#include <vector>

#include "core/input_error.hpp"

namespace demscale::io {

class TomlReader {
public:
    // Throws InputError for a missing file or malformed TOML; then checks every section and key
    // against `schema` (section → allowed keys).
    TomlReader(const std::string& path, const std::map<std::string, std::vector<std::string_view>>& schema);

    const std::string& path() const { return path_; }
    std::optional<double> number(const std::string& dotted) const;
    std::optional<std::string> text(const std::string& dotted) const;
    std::optional<bool> boolean(const std::string& dotted) const;
    std::optional<std::vector<double>> numbers(const std::string& dotted) const;
    // Whether the key is given, whatever its value.
    bool has(const std::string& dotted) const { return root_.at_path(dotted).node() != nullptr; }

    // Reads a number and checks it with `validate` (which throws InputError); the error is prefixed
    // with file and line. Returns `fallback` when the key is absent.
    template <class Validate>
    double checked(const std::string& dotted, double fallback, Validate&& validate) const {
        const auto x = number(dotted);
        if (!x) return fallback;
        check(dotted, [&] { validate(*x, dotted); });
        return *x;
    }

    // Runs a validation and prefixes its error with file and line of `dotted`.
    template <class F>
    void check(const std::string& dotted, F&& validate) const {
        try {
            validate();
        } catch (const InputError& e) {
            const std::string field = e.field().rfind(dotted, 0) == 0 ? e.field() : dotted;
            throw InputError(where(dotted, field), e.value(), e.accepted());
        }
    }

    // "FILE:LINE: field" for the node at `dotted` (or the file alone when absent).
    std::string where(const std::string& dotted, const std::string& field) const;

private:
    std::string path_;
    toml::table root_;
};

}  // namespace demscale::io
