#include "app/cluster/sweep_set.h"

#include "app/scene/json_reader.h"
#include "io/bad_input.h"

#include <charconv>

namespace tumble::app {

namespace {

io::BadInput bad_set(const std::string& text, const std::string& why) {
    return io::BadInput("--set " + text + ": " + why);
}

// Splits at commas that are not inside [], {} or a "string".
std::vector<std::string> split_values(const std::string& list) {
    std::vector<std::string> out(1);
    int depth = 0;
    bool quoted = false;
    for (std::size_t i = 0; i < list.size(); ++i) {
        const char c = list[i];
        if (quoted && c == '\\' && i + 1 < list.size()) {
            out.back() += c;
            out.back() += list[++i];
            continue;
        }
        if (c == '"') quoted = !quoted;
        if (!quoted && (c == '[' || c == '{')) ++depth;
        if (!quoted && (c == ']' || c == '}')) --depth;
        if (!quoted && depth == 0 && c == ',') {
            out.emplace_back();
            continue;
        }
        out.back() += c;
    }
    return out;
}

std::vector<std::string> split_path(const std::string& path) {
    std::vector<std::string> keys;
    if (path.starts_with('/')) { // a JSON pointer, with its own escapes (~0, ~1)
        nlohmann::json::json_pointer p(path);
        while (!p.empty()) {
            keys.insert(keys.begin(), p.back());
            p.pop_back();
        }
        return keys;
    }
    std::string key;
    for (const char c : path + ".") {
        if (c != '.') {
            key += c;
            continue;
        }
        keys.push_back(key);
        key.clear();
    }
    return keys;
}

bool array_index(const std::string& key, std::size_t& index) {
    const auto [at, ec] = std::from_chars(key.data(), key.data() + key.size(), index);
    return ec == std::errc() && at == key.data() + key.size() && !key.empty();
}

} // namespace

std::string SweepSet::pointer() const {
    std::string p;
    for (const std::string& k : keys) p.append("/").append(json_pointer_segment(k));
    return p;
}

SweepSet parse_set(const std::string& text) {
    SweepSet s;
    s.text = text;
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
        throw bad_set(text, "expected PATH=VALUE[,VALUE...], e.g. world.integrator=euler,rk4");
    s.path = text.substr(0, eq);
    try {
        s.keys = split_path(s.path);
    } catch (const nlohmann::json::exception& e) {
        throw bad_set(text, std::string("not a JSON pointer: ") + e.what());
    }
    for (const std::string& k : s.keys)
        if (k.empty()) throw bad_set(text, "the path " + s.path + " has an empty field name");
    for (const std::string& v : split_values(text.substr(eq + 1))) {
        if (v.empty()) throw bad_set(text, "an empty value (two commas, or one at an end)");
        nlohmann::json value = nlohmann::json::parse(v, nullptr, false);
        s.values.push_back(value.is_discarded() ? nlohmann::json(v) : value);
    }
    return s;
}

void apply_set(nlohmann::json& scene, const SweepSet& set, const nlohmann::json& value,
               const std::string& file) {
    nlohmann::json* at = &scene;
    std::string path;
    for (std::size_t i = 0; i < set.keys.size(); ++i) {
        const std::string& key = set.keys[i];
        const bool last = i + 1 == set.keys.size();
        const auto refuse = [&](const std::string& why) {
            return bad_set(set.text, file + ": " + (path.empty() ? "/" : path) + ": " + why);
        };
        if (at->is_array()) {
            std::size_t index = 0;
            if (!array_index(key, index) || index >= at->size())
                throw refuse("expected an index into this array of " + std::to_string(at->size()) +
                             (at->empty() ? "" : " (0 to " + std::to_string(at->size() - 1) + ")") +
                             ", got " + key);
            at = &(*at)[index];
        } else if (at->is_object()) {
            if (!at->contains(key) && !last) (*at)[key] = nlohmann::json::object();
            at = &(*at)[key];
        } else {
            throw refuse("is " + describe_json(*at) + ", which has no field " + key);
        }
        path.append("/").append(json_pointer_segment(key));
    }
    *at = value;
}

} // namespace tumble::app
