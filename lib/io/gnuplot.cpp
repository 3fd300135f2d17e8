#include "io/gnuplot.hpp"

#include <spawn.h>
#include <stdexcept>
#include <string>
#include <sys/wait.h>
#include <vector>

#include "io/atomic_file.hpp"

extern char** environ;

namespace demscale::io {

std::string gnuplot_literal(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '_' || c == '^' || c == '@' || c == '&' || c == '{' || c == '}') out += "\\\\";
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out;
}

namespace fs = std::filesystem;

namespace {
int run(std::vector<std::string> argv) {
    std::vector<char*> args;
    for (auto& a : argv) args.push_back(a.data());
    args.push_back(nullptr);
    pid_t pid;
    if (posix_spawnp(&pid, args[0], nullptr, nullptr, args.data(), environ) != 0) return 127;
    int status = 0;
    if (waitpid(pid, &status, 0) < 0) return 127;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

std::string gnuplot_string(const fs::path& p) {
    const std::string s = p.string();
    if (s.find('\'') != std::string::npos) throw std::runtime_error("path contains a single quote: " + s);
    return "'" + s + "'";
}
}  // namespace

bool gnuplot_available() { return run({"gnuplot", "-e", "exit"}) == 0; }

void render_gnuplot(const fs::path& script, const fs::path& png_target) {
    PendingFile png(fs::absolute(png_target));
    const fs::path dir = fs::absolute(script).parent_path();
    const int rc = run({"gnuplot", "-e",
                        "cd " + gnuplot_string(dir) + "; outfile = " + gnuplot_string(png.temporary()),
                        fs::absolute(script).string()});
    if (rc != 0)
        throw std::runtime_error("gnuplot failed on " + script.string() + " (exit " + std::to_string(rc) +
                                 (rc == 127 ? ": gnuplot not found, install gnuplot-nox or pass --no-png)" : ")"));
    if (!fs::exists(png.temporary()) || fs::file_size(png.temporary()) == 0)
        throw std::runtime_error("gnuplot wrote no image for " + script.string());
    png.commit();
}

}  // namespace demscale::io
