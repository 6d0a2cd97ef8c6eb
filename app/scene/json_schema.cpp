#include "app/scene/json_schema.h"

#include <map>

namespace tumble::app {
namespace {

using Json = nlohmann::ordered_json;

// An integer's bounds as integers (64, not 64.0), a number's as they are.
Json bound(const Type& t, double v) {
    if (t.kind == Type::Kind::kInteger) return static_cast<long long>(v);
    return v;
}

class SchemaWriter {
  public:
    Json table(const Table& t) {
        Json out = {{"type", "object"}};
        if (!t.description.empty()) out["description"] = t.description;
        Json properties = Json::object();
        Json required = Json::array();
        for (const Field& f : t.fields) {
            Json p = type(f.type);
            p["description"] = f.expected;
            properties[f.name] = p;
            if (f.required) required.push_back(f.name);
        }
        out["properties"] = properties;
        if (!required.empty()) out["required"] = required;
        out["additionalProperties"] = false;
        return out;
    }

    // Every table reached from the root, under its id, each once.
    Json defs() {
        Json out = Json::object();
        while (!pending_.empty()) {
            const Table& t = *pending_.begin()->second;
            pending_.erase(pending_.begin());
            if (done_.count(t.id)) continue;
            done_[t.id] = true;
            out[t.id] = table(t);
        }
        return out;
    }

  private:
    Json type(const Type& t) {
        using K = Type::Kind;
        Json out = Json::object();
        switch (t.kind) {
        case K::kNumber:
        case K::kInteger:
            out["type"] = t.kind == K::kNumber ? "number" : "integer";
            if (t.minimum)
                out[t.exclusive_minimum ? "exclusiveMinimum" : "minimum"] = bound(t, *t.minimum);
            if (t.maximum)
                out[t.exclusive_maximum ? "exclusiveMaximum" : "maximum"] = bound(t, *t.maximum);
            break;
        case K::kBoolean:
            out["type"] = "boolean";
            break;
        case K::kString:
            out["type"] = "string";
            if (!t.one_of.empty()) out["enum"] = t.one_of;
            if (!t.pattern.empty()) out["pattern"] = t.pattern;
            break;
        case K::kArray:
            out["type"] = "array";
            if (t.items) {
                out["items"] = type(t.items->type);
                out["items"]["description"] = t.items->expected;
            }
            if (t.min_items) out["minItems"] = *t.min_items;
            if (t.max_items) out["maxItems"] = *t.max_items;
            break;
        case K::kObject: {
            const Table& nested = t.table();
            if (!done_.count(nested.id)) pending_.emplace(nested.id, &nested);
            out["$ref"] = "#/$defs/" + nested.id;
            break;
        }
        case K::kMap:
            out["type"] = "object";
            out["additionalProperties"] = type(t.items->type);
            out["additionalProperties"]["description"] = t.items->expected;
            break;
        case K::kAnyOf:
            out["anyOf"] = Json::array();
            for (const Type& a : t.alternatives) out["anyOf"].push_back(type(a));
            break;
        }
        return out;
    }

    std::map<std::string, const Table*> pending_;
    std::map<std::string, bool> done_;
};

} // namespace

nlohmann::ordered_json json_schema(const Table& root, const std::string& id,
                                   const std::string& title) {
    SchemaWriter w;
    Json out = {
        {"$schema", "https://json-schema.org/draft/2020-12/schema"}, {"$id", id}, {"title", title}};
    const Json body = w.table(root);
    for (auto it = body.begin(); it != body.end(); ++it) out[it.key()] = it.value();
    const Json defs = w.defs();
    if (!defs.empty()) out["$defs"] = defs;
    return out;
}

} // namespace tumble::app
