#pragma once
// A fingerprint of input bytes (a scene file and the mesh files it reads), to tell whether two
// runs, or a run and a checkpoint or video shard made earlier, come from the same inputs: 64-bit
// FNV-1a (Fowler, Noll, Vo), byte by byte, shown as 16 hex digits. It detects accidental
// differences (an edited file, another scene); it is not a cryptographic hash and does not resist
// inputs made on purpose to collide. Two different inputs share a value with probability about
// 2^-64 per pair.
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace tumble::app {

class ContentHash {
  public:
    // Each piece is prefixed by its length, so ("ab", "c") and ("a", "bc") differ.
    void add(std::string_view bytes) {
        const std::uint64_t n = bytes.size();
        for (int i = 0; i < 8; ++i) mix(static_cast<unsigned char>(n >> (8 * i)));
        for (const char c : bytes) mix(static_cast<unsigned char>(c));
    }
    std::uint64_t value() const { return h_; }
    std::string hex() const { return to_hex(h_); }

    static std::string to_hex(std::uint64_t v) {
        char text[17];
        std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(v));
        return text;
    }

  private:
    void mix(unsigned char byte) {
        h_ ^= byte;
        h_ *= 0x100000001b3ull; // the 64-bit FNV prime
    }
    std::uint64_t h_ = 0xcbf29ce484222325ull; // the 64-bit FNV offset basis
};

} // namespace tumble::app
