#include "app/scene/obj_lines.h"

#include <charconv>
#include <cmath>
#include <string_view>
#include <vector>

namespace tumble::app {
namespace {

// The words of `line` (split at spaces and tabs) up to a '#'.
std::vector<std::string_view> words(std::string_view line) {
    line = line.substr(0, line.find('#'));
    std::vector<std::string_view> out;
    std::size_t at = 0;
    while ((at = line.find_first_not_of(" \t\r", at)) != std::string_view::npos) {
        const std::size_t end = std::min(line.find_first_of(" \t\r", at), line.size());
        out.push_back(line.substr(at, end - at));
        at = end;
    }
    return out;
}

std::string quoted(std::string_view s) {
    constexpr std::size_t kExcerpt = 60;
    std::string out(1, '"');
    out.append(s.substr(0, kExcerpt));
    out.append(s.size() > kExcerpt ? "...\"" : "\"");
    return out;
}

bool finite_number(std::string_view s) {
    double x = 0.0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), x);
    return ec == std::errc() && end == s.data() + s.size() && std::isfinite(x);
}

bool integer(std::string_view s, long long& out) {
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && end == s.data() + s.size();
}

std::optional<std::string> check_vertex(const std::vector<std::string_view>& w) {
    const std::size_t n = w.size() - 1;
    if (n != 3 && n != 4 && n != 6)
        return "expected a vertex \"v x y z\" of 3 numbers (4 with a weight, 6 with a colour), "
               "got " +
               std::to_string(n);
    for (std::size_t k = 1; k < w.size(); ++k)
        if (!finite_number(w[k]))
            return "expected a finite number as vertex coordinate " + std::to_string(k) + ", got " +
                   quoted(w[k]);
    return std::nullopt;
}

// Whether `p` is a non-zero integer; `empty_ok` lets it be absent (the vt of "v//vn").
bool index_part(std::string_view p, bool empty_ok) {
    long long x = 0;
    return (empty_ok && p.empty()) || (integer(p, x) && x != 0);
}

// One corner "v", "v/vt", "v//vn" or "v/vt/vn" of a face, with `read` vertices read so far of
// `total` in the file.
std::optional<std::string> check_corner(std::string_view c, long long read, long long total) {
    std::vector<std::string_view> parts;
    for (std::size_t at = 0;;) {
        const std::size_t slash = c.find('/', at);
        parts.push_back(c.substr(at, slash == std::string_view::npos ? slash : slash - at));
        if (slash == std::string_view::npos) break;
        at = slash + 1;
    }
    const bool ok = parts.size() <= 3 && index_part(parts[0], false) &&
                    (parts.size() < 2 || index_part(parts[1], parts.size() == 3)) &&
                    (parts.size() < 3 || index_part(parts[2], false));
    if (!ok)
        return "expected a vertex index (\"v\", \"v/vt\", \"v//vn\" or \"v/vt/vn\", non-zero "
               "integers), got " +
               quoted(c);
    long long v = 0;
    integer(parts[0], v);
    const long long count = v > 0 ? total : read, index = v > 0 ? v : read + v + 1;
    if (index < 1 || index > count)
        return "vertex index " + std::to_string(v) + " is out of range: " + std::to_string(count) +
               (v > 0 ? " vertices in the file" : " vertices read before this line");
    return std::nullopt;
}

} // namespace

std::optional<ObjLineError> check_obj_lines(const std::string& text) {
    std::vector<std::string_view> lines;
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t end = std::min(text.find('\n', at), text.size());
        lines.push_back(std::string_view(text).substr(at, end - at));
        at = end + 1;
    }
    long long total = 0;
    for (std::string_view line : lines) {
        const auto w = words(line);
        total += !w.empty() && w[0] == "v";
    }
    long long read = 0;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::vector<std::string_view> w = words(lines[i]);
        std::optional<std::string> why;
        if (!w.empty() && w[0] == "v") {
            why = check_vertex(w);
            ++read;
        } else if (!w.empty() && w[0] == "f") {
            if (w.size() < 4)
                why = "expected a face of at least 3 vertices, got " + std::to_string(w.size() - 1);
            for (std::size_t k = 1; k < w.size() && !why; ++k)
                why = check_corner(w[k], read, total);
        }
        if (why) return ObjLineError{i + 1, *why};
    }
    return std::nullopt;
}

} // namespace tumble::app
