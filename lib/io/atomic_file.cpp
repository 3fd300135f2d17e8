#include "io/atomic_file.hpp"

#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace demscale::io {

namespace fs = std::filesystem;

namespace {
fs::path temporary_beside(const fs::path& target) {
    // Keep the extension last so programs that look at it (gnuplot's terminals do not, viewers do) still work.
    return target.parent_path() /
           ("." + target.stem().string() + ".tmp" + std::to_string(::getpid()) + target.extension().string());
}
void ensure_parent(const fs::path& target) {
    if (target.has_parent_path()) fs::create_directories(target.parent_path());
}
}  // namespace

void write_file_atomically(const fs::path& target, const std::string& content) {
    ensure_parent(target);
    const fs::path tmp = temporary_beside(target);
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out << content;
        out.flush();
        if (!out) {
            std::error_code ignored;
            fs::remove(tmp, ignored);
            throw std::runtime_error("cannot write " + target.string());
        }
    }
    std::error_code ec;
    fs::rename(tmp, target, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw std::runtime_error("cannot replace " + target.string() + ": " + ec.message());
    }
}

PendingFile::PendingFile(fs::path target) : target_(std::move(target)), temporary_(temporary_beside(target_)) {
    ensure_parent(target_);
}

PendingFile::~PendingFile() {
    if (!committed_) {
        std::error_code ignored;
        fs::remove(temporary_, ignored);
    }
}

void PendingFile::commit() {
    std::error_code ec;
    fs::rename(temporary_, target_, ec);
    if (ec) throw std::runtime_error("cannot replace " + target_.string() + ": " + ec.message());
    committed_ = true;
}

}  // namespace demscale::io
