#pragma once
// Little-endian bytes in and out, for the binary checkpoint format (checkpoint.h). Numbers are
// written byte by byte from their bit patterns, so the file is the same on any host and a double
// comes back with exactly the bits it had. The reader checks every length against what is left,
// so a truncated or damaged file is an error naming the byte where it broke, never a read past
// the end or a huge allocation.
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>

namespace tumble::app {

class ByteWriter {
  public:
    template <class T>
    void number(T value) {
        static_assert(sizeof(T) <= 8);
        std::uint64_t bits = 0;
        std::memcpy(&bits, &value, sizeof(T));
        for (std::size_t i = 0; i < sizeof(T); ++i)
            out_.push_back(static_cast<char>((bits >> (8 * i)) & 0xffu));
    }
    void text(std::string_view s) {
        number(static_cast<std::uint32_t>(s.size()));
        out_.append(s);
    }
    void raw(std::string_view s) { out_.append(s); }
    const std::string& bytes() const { return out_; }

  private:
    std::string out_;
};

// Thrown by ByteReader; the caller adds the file's name.
struct TruncatedBytes : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class ByteReader {
  public:
    explicit ByteReader(std::string_view bytes) : in_(bytes) {}

    template <class T>
    T number() {
        static_assert(sizeof(T) <= 8);
        need(sizeof(T), "a number");
        std::uint64_t bits = 0;
        for (std::size_t i = 0; i < sizeof(T); ++i)
            bits |= std::uint64_t(static_cast<unsigned char>(in_[at_ + i])) << (8 * i);
        at_ += sizeof(T);
        T value;
        std::memcpy(&value, &bits, sizeof(T));
        return value;
    }
    std::string text() {
        const auto n = number<std::uint32_t>();
        need(n, "a string");
        std::string s(in_.substr(at_, n));
        at_ += n;
        return s;
    }
    std::string_view raw(std::size_t n, const char* what) {
        need(n, what);
        const std::string_view s = in_.substr(at_, n);
        at_ += n;
        return s;
    }
    std::size_t offset() const { return at_; }
    std::size_t left() const { return in_.size() - at_; }

  private:
    void need(std::size_t n, const char* what) const {
        if (n > left())
            throw TruncatedBytes("the file ends at byte " + std::to_string(in_.size()) +
                                 " inside " + what + " starting at byte " + std::to_string(at_));
    }
    std::string_view in_;
    std::size_t at_ = 0;
};

} // namespace tumble::app
