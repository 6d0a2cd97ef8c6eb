#include "app/scene/field_table.h"

#include <algorithm>
#include <stdexcept>

namespace tumble::app {

namespace types {

Type number() {
    return {};
}
Type positive() {
    Type t;
    t.minimum = 0.0;
    t.exclusive_minimum = true;
    return t;
}
Type non_negative() {
    Type t;
    t.minimum = 0.0;
    return t;
}
Type number_in(double lo, double hi) {
    Type t;
    t.minimum = lo;
    t.maximum = hi;
    return t;
}
Type positive_below(double hi) {
    Type t = positive();
    t.maximum = hi;
    t.exclusive_maximum = true;
    return t;
}
Type integer(int lo, int hi) {
    Type t;
    t.kind = Type::Kind::kInteger;
    t.minimum = lo;
    t.maximum = hi;
    return t;
}
Type boolean() {
    Type t;
    t.kind = Type::Kind::kBoolean;
    return t;
}
Type string() {
    Type t;
    t.kind = Type::Kind::kString;
    return t;
}
Type one_of(std::vector<std::string> values) {
    Type t = string();
    t.one_of = std::move(values);
    return t;
}
Type pattern(std::string regex) {
    Type t = string();
    t.pattern = std::move(regex);
    return t;
}
Type vec3() {
    Type t = array_of(number(), "a finite number");
    t.min_items = t.max_items = 3;
    return t;
}
Type array_of(Type items, std::string expected, std::size_t min_items) {
    Type t;
    t.kind = Type::Kind::kArray;
    t.items = std::make_shared<const Field>(Field{"", std::move(items), std::move(expected)});
    if (min_items > 0) t.min_items = min_items;
    return t;
}
Type object(const Table& (*table)()) {
    Type t;
    t.kind = Type::Kind::kObject;
    t.table = table;
    return t;
}
Type map_of(Type values, std::string expected) {
    Type t = array_of(std::move(values), std::move(expected));
    t.kind = Type::Kind::kMap;
    return t;
}
Type any_of(std::vector<Type> alternatives) {
    Type t;
    t.kind = Type::Kind::kAnyOf;
    t.alternatives = std::move(alternatives);
    return t;
}

} // namespace types

const Field& Table::operator[](std::string_view name) const {
    for (const Field& f : fields)
        if (f.name == name) return f;
    throw std::logic_error("table " + id + " has no field " + std::string(name));
}

double FieldValue::number() const {
    const Type& t = f_->type;
    const double x = r_.number(f_->expected.c_str());
    const bool low = t.minimum && (t.exclusive_minimum ? !(x > *t.minimum) : x < *t.minimum);
    const bool high = t.maximum && (t.exclusive_maximum ? !(x < *t.maximum) : x > *t.maximum);
    if (low || high) fail("expected " + f_->expected + ", got " + describe_json(value()));
    return x;
}

int FieldValue::integer() const {
    const Type& t = f_->type;
    const int lo = t.minimum ? static_cast<int>(*t.minimum) : -(1 << 30);
    const int hi = t.maximum ? static_cast<int>(*t.maximum) : 1 << 30;
    return r_.integer(lo, hi, f_->expected.c_str());
}

bool FieldValue::boolean() const {
    return r_.boolean();
}

std::string FieldValue::string() const {
    return r_.string();
}

std::string FieldValue::choice() const {
    const std::string s = r_.string();
    std::string all;
    for (const std::string& v : f_->type.one_of) {
        if (v == s) return s;
        all += (all.empty() ? "" : ", ") + v;
    }
    fail("expected " + f_->expected + " (one of: " + all + "), got " + describe_json(value()));
}

std::array<double, 3> FieldValue::vec3() const {
    return r_.vec3(f_->expected.c_str());
}

std::size_t FieldValue::size() const {
    const std::size_t n = r_.size();
    const Type& t = f_->type;
    if (t.min_items && n < *t.min_items)
        fail("expected " + f_->expected + " (at least " + std::to_string(*t.min_items) + "), got " +
             describe_json(value()));
    if (t.max_items && n > *t.max_items)
        fail("expected " + f_->expected + " (at most " + std::to_string(*t.max_items) + "), got " +
             describe_json(value()));
    return n;
}

FieldValue FieldValue::at(std::size_t index) const {
    if (!f_->type.items) throw std::logic_error("field " + f_->name + " is not an array");
    return FieldValue(r_.at(index), *f_->type.items);
}

ObjectReader::ObjectReader(JsonReader reader, const Table& table)
    : r_(std::move(reader)), t_(&table) {
    if (!r_.value().is_object())
        r_.fail("expected " + (table.description.empty() ? "an object" : table.description) +
                " (an object), got " + describe_json(r_.value()));
}

bool ObjectReader::has(std::string_view name) const {
    return r_.value().contains((*t_)[name].name);
}

FieldValue ObjectReader::field(std::string_view name) {
    const Field& f = (*t_)[name];
    return FieldValue(r_.field(f.name.c_str()), f);
}

std::optional<FieldValue> ObjectReader::optional(std::string_view name) {
    const Field& f = (*t_)[name];
    if (auto r = r_.optional(f.name.c_str())) return FieldValue(*r, f);
    return std::nullopt;
}

void ObjectReader::finish() const {
    std::vector<std::string> known;
    for (const Field& f : t_->fields) known.push_back(f.name);
    for (auto it = r_.value().begin(); it != r_.value().end(); ++it) {
        const std::string& key = it.key();
        if (std::find(known.begin(), known.end(), key) != known.end()) continue;
        std::string what = "unknown field " + describe_json(key); // cut if long
        const std::string guess = key.size() > 60 ? "" : closest_match(key, known);
        if (!guess.empty()) what += " (did you mean \"" + guess + "\"?)";
        std::string fields;
        for (const std::string& k : known) fields += (fields.empty() ? "" : ", ") + k;
        r_.fail_at(key, what + "; fields allowed here: " + fields);
    }
}

} // namespace tumble::app
