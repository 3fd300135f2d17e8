// Reading a file a user named: one place that tells "not found", "a directory" and "unreadable"
// apart, so every command answers a bad path with the same clear InputError (exit 2).
#pragma once

#include <string>

namespace demscale::io {

// The whole content of `path`. field: what named it (an option such as --scene, or "reference");
// what: the kind of file expected, for the message ("a TOML scene file").
std::string read_input_file(const std::string& field, const std::string& path, const std::string& what);

}  // namespace demscale::io
