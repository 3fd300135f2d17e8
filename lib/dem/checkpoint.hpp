// One binary checkpoint format, for the engine and for the protocols that drive it: a 16-byte tag
// naming the format and its version, then plain values and arrays (a 64-bit count, then the
// elements' bytes). A reader refuses another tag with a message, and a truncated or absurd file
// with another; nothing is read past what was written. Fixed-size data without pointers only.
#pragma once

#include <cstdint>
#include <cstring>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace demscale::dem {

using CheckpointTag = char[16];

class CheckpointWriter {
public:
    CheckpointWriter(std::ostream& out, const CheckpointTag& tag) : out_(out) { bytes(tag, sizeof(CheckpointTag)); }
    template <class T>
    void value(const T& x) {
        static_assert(std::is_standard_layout_v<T>);  // fixed-size data written as bytes (Eigen vectors included)
        bytes(&x, sizeof x);
    }
    template <class T>
    void array(const std::vector<T>& v) {
        static_assert(std::is_standard_layout_v<T>);  // fixed-size data written as bytes (Eigen vectors included)
        const std::uint64_t n = v.size();
        bytes(&n, sizeof n);
        bytes(v.data(), n * sizeof(T));
    }
    void bytes(const void* data, std::size_t size) {
        out_.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
        if (!out_) throw std::runtime_error("cannot write checkpoint");
    }

private:
    std::ostream& out_;
};

class CheckpointReader {
public:
    // Throws std::runtime_error "<what_else>" when the tag is another (another format or version).
    CheckpointReader(std::istream& in, const CheckpointTag& tag, const std::string& what_else) : in_(in) {
        char found[sizeof(CheckpointTag)];
        bytes(found, sizeof found);
        if (std::memcmp(found, tag, sizeof found) != 0) throw std::runtime_error(what_else);
    }
    template <class T>
    void value(T& x) {
        static_assert(std::is_standard_layout_v<T>);  // fixed-size data written as bytes (Eigen vectors included)
        bytes(&x, sizeof x);
    }
    template <class T>
    void array(std::vector<T>& v) {
        static_assert(std::is_standard_layout_v<T>);  // fixed-size data written as bytes (Eigen vectors included)
        std::uint64_t n = 0;
        bytes(&n, sizeof n);
        if (n > (1ULL << 34) / sizeof(T) + 1) throw std::runtime_error("checkpoint corrupt (array of " + std::to_string(n) + ")");
        v.resize(n);
        bytes(v.data(), n * sizeof(T));
    }
    void bytes(void* data, std::size_t size) {
        in_.read(static_cast<char*>(data), static_cast<std::streamsize>(size));
        if (!in_) throw std::runtime_error("checkpoint truncated or unreadable");
    }

private:
    std::istream& in_;
};

}  // namespace demscale::dem
