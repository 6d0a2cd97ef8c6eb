#pragma once
// Reading a JSON scene with exact error places. A JsonReader wraps one JSON value and its path
// (RFC 6901 style, e.g. /bodies/2/shape/radius); every accessor checks the type and range it
// expects and throws SceneError naming the file, the path and what was expected. finish() refuses
// keys nobody read, so a misspelt field ("colour") is an error, not silently ignored.
#include "app/scene/scene_error.h"

#include <nlohmann/json.hpp>

#include <array>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace tumble::app {

class JsonReader {
  public:
    JsonReader(const nlohmann::json& value, std::string file, std::string path);

    const std::string& path() const { return path_; }
    const nlohmann::json& value() const { return value_; }
    [[noreturn]] void fail(const std::string& what) const;
    // The same at this object's key `key` (which need not exist): "<path>/<key>: what".
    [[noreturn]] void fail_at(const std::string& key, const std::string& what) const;

    // Object access. has() marks nothing; field()/optional() mark the key as read.
    bool has(const char* key) const;
    JsonReader field(const char* key);
    std::optional<JsonReader> optional(const char* key);
    void finish() const; // every key of this object was read, or SceneError (with a suggestion)

    // Array access.
    std::size_t size() const;
    JsonReader at(std::size_t index) const;

    // Scalars. `what` completes "expected ..." (e.g. "a positive number of seconds").
    double number(const char* what) const;       // finite
    double positive(const char* what) const;     // finite, > 0
    double non_negative(const char* what) const; // finite, >= 0
    int integer(int min, int max, const char* what) const;
    bool boolean() const;
    std::string string() const;
    std::array<double, 3> vec3(const char* what) const; // [x, y, z], finite

  private:
    JsonReader child(const nlohmann::json& v, const std::string& segment) const;
    void expect_object() const;

    const nlohmann::json& value_;
    std::string file_;
    std::string path_;
    std::set<std::string> read_;
};

// One segment of a JSON path (RFC 6901: '~' as "~0", '/' as "~1"), a long key cut to 60 bytes
// and "...".
std::string json_pointer_segment(const std::string& key);

// A short, flat description of `v` for an error message, never longer than about 100
// characters and never recursing: a number, boolean or null as written; a string quoted and cut
// to 60 bytes; a few numbers in brackets as written ("[0.2,0,0.3]"); any other array or object
// by its size ("an array of 1000000 elements", "an object with 3 keys").
std::string describe_json(const nlohmann::json& v);

// Parses `text` (the contents of `file`). Syntax errors (a NUL byte among them), and arrays and
// objects nested deeper than kMaxJsonDepth (app/scene/json_nesting.h), become SceneError with
// line:column; a key twice in one object (app/scene/json_duplicate_keys.h), SceneError at its
// JSON path naming both places.
nlohmann::json parse_json(const std::string& text, const std::string& file);

// Closest of `candidates` to `word` by edit distance, or empty if none is close.
std::string closest_match(const std::string& word, const std::vector<std::string>& candidates);

} // namespace tumble::app
