#include "io/input_file.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/input_error.hpp"

namespace demscale::io {

std::string read_input_file(const std::string& field, const std::string& path, const std::string& what) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const auto status = fs::status(path, ec);
    if (!fs::exists(status)) throw InputError(field, path, what + " (not found)");
    if (fs::is_directory(status)) throw InputError(field, path, what + " (this is a directory)");
    if (!fs::is_regular_file(status)) throw InputError(field, path, what + " (not a regular file)");
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    if (in) text << in.rdbuf();
    if (!in || in.bad()) throw InputError(field, path, what + " (unreadable: permission denied or I/O error)");
    return text.str();
}

}  // namespace demscale::io
