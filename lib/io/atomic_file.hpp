// Outputs appear whole or not at all: content goes to a temporary file beside the target,
// which is renamed over it only once complete. A reader never sees a partial file.
#pragma once

#include <filesystem>
#include <string>

namespace demscale::io {

// Creates parent directories as needed. Throws std::runtime_error naming the path on failure.
void write_file_atomically(const std::filesystem::path& target, const std::string& content);

// For files another program writes (gnuplot's PNG): hands out a temporary path beside the
// target; commit() renames it over the target, the destructor removes it if not committed.
class PendingFile {
public:
    explicit PendingFile(std::filesystem::path target);
    ~PendingFile();
    PendingFile(const PendingFile&) = delete;
    PendingFile& operator=(const PendingFile&) = delete;

    const std::filesystem::path& temporary() const { return temporary_; }
    void commit();

private:
    std::filesystem::path target_, temporary_;
    bool committed_ = false;
};

}  // namespace demscale::io
