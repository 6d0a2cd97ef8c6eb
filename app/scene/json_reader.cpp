#include "app/scene/json_reader.h"

#include "app/scene/json_duplicate_keys.h"
#include "app/scene/json_nesting.h"
#include "app/scene/text_place.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tumble::app {
namespace {

constexpr std::size_t kExcerpt = 60; // characters of a value an error message quotes

// `s` cut to at most `n` bytes, not inside a UTF-8 sequence.
std::string utf8_prefix(const std::string& s, std::size_t n) {
    if (s.size() <= n) return s;
    while (n > 0 && (static_cast<unsigned char>(s[n]) & 0xC0) == 0x80) --n;
    return s.substr(0, n);
}

std::string flat_dump(const nlohmann::json& v) {
    return v.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

// An array of a few numbers, booleans or nulls: short enough to quote whole.
bool small_flat_array(const nlohmann::json& v) {
    if (!v.is_array() || v.size() > 8) return false;
    return std::all_of(v.begin(), v.end(), [](const nlohmann::json& e) {
        return e.is_number() || e.is_boolean() || e.is_null();
    });
}

std::string count(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        cur[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j)
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] != b[j - 1])});
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

} // namespace

std::string json_pointer_segment(const std::string& key) {
    // RFC 6901: '~' -> "~0", '/' -> "~1".
    const bool cut = key.size() > kExcerpt;
    std::string out;
    for (char c : cut ? utf8_prefix(key, kExcerpt) : key)
        out += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
    return cut ? out + "..." : out;
}

std::string describe_json(const nlohmann::json& v) {
    if (v.is_string()) {
        const auto& s = v.get_ref<const std::string&>();
        if (s.size() <= kExcerpt) return flat_dump(v);
        return flat_dump(utf8_prefix(s, kExcerpt)) + "... (a string of " +
               count(s.size(), "byte", "bytes") + ")";
    }
    if (v.is_object()) return "an object with " + count(v.size(), "key", "keys");
    if (v.is_array() && !small_flat_array(v))
        return "an array of " + count(v.size(), "element", "elements");
    const std::string text = flat_dump(v); // a scalar, or a few of them in brackets
    return text.size() <= kExcerpt ? text : text.substr(0, kExcerpt) + "...";
}

JsonReader::JsonReader(const nlohmann::json& value, std::string file, std::string path)
    : value_(value), file_(std::move(file)), path_(path.empty() ? "/" : std::move(path)) {}

void JsonReader::fail(const std::string& what) const {
    throw SceneError(file_, path_, what);
}

void JsonReader::fail_at(const std::string& key, const std::string& what) const {
    throw SceneError(file_, (path_ == "/" ? "" : path_) + "/" + json_pointer_segment(key), what);
}

JsonReader JsonReader::child(const nlohmann::json& v, const std::string& segment) const {
    return JsonReader(v, file_, (path_ == "/" ? "" : path_) + "/" + segment);
}

void JsonReader::expect_object() const {
    if (!value_.is_object()) fail(std::string("expected an object, got ") + value_.type_name());
}

bool JsonReader::has(const char* key) const {
    expect_object();
    return value_.contains(key);
}

JsonReader JsonReader::field(const char* key) {
    expect_object();
    auto it = value_.find(key);
    if (it == value_.end()) fail(std::string("missing required field \"") + key + "\"");
    read_.insert(key);
    return child(*it, json_pointer_segment(key));
}

std::optional<JsonReader> JsonReader::optional(const char* key) {
    expect_object();
    read_.insert(key);
    auto it = value_.find(key);
    if (it == value_.end()) return std::nullopt;
    return child(*it, json_pointer_segment(key));
}

void JsonReader::finish() const {
    expect_object();
    std::vector<std::string> known(read_.begin(), read_.end());
    for (auto it = value_.begin(); it != value_.end(); ++it) {
        if (read_.count(it.key())) continue;
        std::string what = "unknown field " + describe_json(it.key()); // cut if long
        const bool long_key = it.key().size() > kExcerpt;
        const std::string guess = long_key ? "" : closest_match(it.key(), known);
        if (!guess.empty()) what += " (did you mean \"" + guess + "\"?)";
        std::string fields;
        for (const std::string& k : known) fields += (fields.empty() ? "" : ", ") + k;
        what += "; fields allowed here: " + fields;
        throw SceneError(file_, (path_ == "/" ? "" : path_) + "/" + json_pointer_segment(it.key()),
                         what);
    }
}

std::size_t JsonReader::size() const {
    if (!value_.is_array()) fail(std::string("expected an array, got ") + value_.type_name());
    return value_.size();
}

JsonReader JsonReader::at(std::size_t index) const {
    return child(value_.at(index), std::to_string(index));
}

double JsonReader::number(const char* what) const {
    if (!value_.is_number())
        fail(std::string("expected ") + what + ", got " + describe_json(value_));
    const double x = value_.get<double>();
    if (!std::isfinite(x)) fail(std::string("expected ") + what + ", got a non-finite number");
    return x;
}

double JsonReader::positive(const char* what) const {
    const double x = number(what);
    if (!(x > 0.0)) fail(std::string("expected ") + what + ", got " + describe_json(value_));
    return x;
}

double JsonReader::non_negative(const char* what) const {
    const double x = number(what);
    if (x < 0.0) fail(std::string("expected ") + what + ", got " + describe_json(value_));
    return x;
}

int JsonReader::integer(int min, int max, const char* what) const {
    if (!value_.is_number_integer())
        fail(std::string("expected ") + what + " (an integer), got " + describe_json(value_));
    const long long x = value_.get<long long>();
    if (x < min || x > max)
        fail(std::string("expected ") + what + " in [" + std::to_string(min) + ", " +
             std::to_string(max) + "], got " + std::to_string(x));
    return static_cast<int>(x);
}

bool JsonReader::boolean() const {
    if (!value_.is_boolean())
        fail(std::string("expected true or false, got ") + describe_json(value_));
    return value_.get<bool>();
}

std::string JsonReader::string() const {
    if (!value_.is_string()) fail(std::string("expected a string, got ") + describe_json(value_));
    return value_.get<std::string>();
}

std::array<double, 3> JsonReader::vec3(const char* what) const {
    if (!value_.is_array() || value_.size() != 3)
        fail(std::string("expected ") + what + " as an array of 3 numbers, got " +
             describe_json(value_));
    std::array<double, 3> out{};
    for (std::size_t k = 0; k < 3; ++k) out[k] = at(k).number("a finite number");
    return out;
}

namespace {

// nlohmann's syntax error from "syntax error" on. It quotes the token it was reading ("...; last
// read: '<token>'[; expected ...]"), which may be the rest of the file: cut it to an excerpt.
std::string syntax_error(std::string what) {
    what.erase(0, std::min(what.find("syntax error"), what.size()));
    const std::string tag = "; last read: '";
    const std::size_t at = what.find(tag);
    if (at == std::string::npos) return what;
    const std::size_t begin = at + tag.size();
    std::size_t end = what.rfind("'; expected "); // a short clause after the token, if any
    if (end == std::string::npos || end < begin || what.size() - end > 100) end = what.size() - 1;
    if (end <= begin + kExcerpt) return what;
    return what.substr(0, begin) + utf8_prefix(what.substr(begin, end - begin), kExcerpt) + "..." +
           what.substr(end);
}

nlohmann::json parse_text(const std::string& text, const std::string& file) {
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw SceneError(file, line_column(text, e.byte == 0 ? 0 : e.byte - 1),
                         "invalid JSON: " + syntax_error(e.what()));
    } catch (const nlohmann::json::out_of_range& e) {
        // A number too large for a double ("number overflow parsing '1e999'"); the exception has
        // no position, so locate the quoted token in the text.
        const std::string what = e.what();
        const auto open = what.find('\''), close = what.rfind('\'');
        const std::string token = open < close ? what.substr(open + 1, close - open - 1) : "";
        const std::size_t at = token.empty() ? std::string::npos : text.find(token);
        throw SceneError(file, at == std::string::npos ? "number" : line_column(text, at),
                         "expected a finite number, got " +
                             (token.size() > kExcerpt ? token.substr(0, kExcerpt) + "..." : token) +
                             " (out of range for a double: non-finite)");
    }
}

} // namespace

nlohmann::json parse_json(const std::string& text, const std::string& file) {
    // nlohmann's parser takes a NUL byte for the end of the text, so "{...}\0anything" would load,
    // and the duplicate-key scan, which trusts the parser, would run off the end of an unclosed
    // string after the NUL. JSON has no raw NUL byte (RFC 8259).
    if (const std::size_t nul = text.find('\0'); nul != std::string::npos)
        throw SceneError(file, line_column(text, nul), "invalid JSON: a NUL byte (a binary file?)");
    check_json_nesting(text, file); // before any tree is built or walked
    nlohmann::json root = parse_text(text, file);
    check_duplicate_keys(text, file); // the parser kept the last of them silently
    return root;
}

std::string closest_match(const std::string& word, const std::vector<std::string>& candidates) {
    std::string best;
    std::size_t best_d = std::numeric_limits<std::size_t>::max();
    for (const std::string& c : candidates) {
        const std::size_t d = edit_distance(word, c);
        if (d < best_d) best_d = d, best = c;
    }
    return best_d <= std::max<std::size_t>(2, word.size() / 3) ? best : std::string();
}

} // namespace tumble::app
