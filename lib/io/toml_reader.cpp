#include "io/toml_reader.hpp"

#include "io/input_file.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/nearest_name.hpp"

namespace demscale::io {

namespace {
std::string location(const std::string& path, const toml::node* node, const std::string& key) {
    std::string s = path;
    if (node && node->source().begin.line > 0) s += ":" + std::to_string(node->source().begin.line);
    return s + ": " + key;
}
}  // namespace

TomlReader::TomlReader(const std::string& path, const std::map<std::string, std::vector<std::string_view>>& schema)
    : path_(path) {
    const std::string text = read_input_file("input file", path, "a readable TOML file");
    try {
        root_ = toml::parse(text, path);
    } catch (const toml::parse_error& e) {
        throw InputError(path + ":" + std::to_string(e.source().begin.line) + ": (TOML syntax)",
                         std::string(e.description()), "well-formed TOML");
    }
    std::vector<std::string_view> sections;
    for (const auto& [name, keys] : schema) sections.push_back(name);
    for (const auto& [key, node] : root_) {
        const std::string section(key.str());
        const auto it = schema.find(section);
        if (it == schema.end())
            throw InputError(location(path, &node, section), "(section)",
                             "a known section (did you mean [" + std::string(nearest_name(section, sections)) + "]?)");
        if (!node.is_table()) throw InputError(location(path, &node, section), "(value)", "a [" + section + "] table");
        for (const auto& [sub, subnode] : *node.as_table()) {
            const std::string name(sub.str());
            if (std::find(it->second.begin(), it->second.end(), std::string_view(name)) == it->second.end())
                throw InputError(location(path, &subnode, section + "." + name), "(unknown key)",
                                 "a key of [" + section + "] (did you mean " + section + "." +
                                     std::string(nearest_name(name, it->second)) + "?)");
        }
    }
}

std::string TomlReader::where(const std::string& dotted, const std::string& field) const {
    return location(path_, root_.at_path(dotted).node(), field);
}

std::optional<double> TomlReader::number(const std::string& dotted) const {
    const toml::node* n = root_.at_path(dotted).node();
    if (!n) return std::nullopt;
    if (auto v = n->value<double>()) {  // integers too
        if (!std::isfinite(*v)) throw InputError(location(path_, n, dotted), format_number(*v), "a finite number");
        return *v;
    }
    throw InputError(location(path_, n, dotted), "(not a number)", "a number");
}

std::optional<std::string> TomlReader::text(const std::string& dotted) const {
    const toml::node* n = root_.at_path(dotted).node();
    if (!n) return std::nullopt;
    if (auto v = n->value<std::string>()) return *v;
    throw InputError(location(path_, n, dotted), "(not a string)", "a quoted string");
}

std::optional<bool> TomlReader::boolean(const std::string& dotted) const {
    const toml::node* n = root_.at_path(dotted).node();
    if (!n) return std::nullopt;
    if (auto v = n->value_exact<bool>()) return *v;  // exact: 1 is not a boolean
    throw InputError(location(path_, n, dotted), "(not a boolean)", "true or false");
}

std::optional<std::vector<double>> TomlReader::numbers(const std::string& dotted) const {
    const toml::node* n = root_.at_path(dotted).node();
    if (!n) return std::nullopt;
    const toml::array* a = n->as_array();
    if (!a) throw InputError(location(path_, n, dotted), "(not an array)", "an array of numbers, e.g. [1.0, 2.0]");
    std::vector<double> out;
    for (std::size_t i = 0; i < a->size(); ++i) {
        auto v = (*a)[i].value<double>();
        const std::string item = dotted + "[" + std::to_string(i) + "]";
        if (!v) throw InputError(location(path_, &(*a)[i], item), "(not a number)", "a number");
        if (!std::isfinite(*v)) throw InputError(location(path_, &(*a)[i], item), format_number(*v), "a finite number");
        out.push_back(*v);
    }
    return out;
}

}  // namespace demscale::io
