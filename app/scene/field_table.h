#pragma once
// Field tables: what an object of a JSON input may hold, declared once and used twice. The loader
// reads every field through its table entry (ObjectReader): the key must be in the table, and the
// type, the range and the words of the error message ("expected a positive time step in seconds")
// come from the entry. `tumble schema` prints the same tables as a JSON Schema (draft 2020-12,
// app/scene/json_schema.h), so an editor's validation and completion say what the loader says.
// What a schema cannot say (a unit quaternion's norm, a mesh being closed, physics) stays in the
// loader's code and is listed in the field's `expected` words.
#include "app/scene/json_reader.h"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tumble::app {

struct Table;
struct Field;

// A JSON type and its constraints, as far as a JSON Schema can state them.
struct Type {
    enum class Kind { kNumber, kInteger, kBoolean, kString, kArray, kObject, kMap, kAnyOf };
    Kind kind = Kind::kNumber;
    std::optional<double> minimum, maximum; // numbers, integers (inclusive)
    bool exclusive_minimum = false;         // minimum excluded (a positive number)
    bool exclusive_maximum = false;         // maximum excluded
    std::vector<std::string> one_of;        // strings: the allowed values (empty: any string)
    std::string pattern;                    // strings: an ECMA-262 regular expression
    std::shared_ptr<const Field> items;     // arrays, maps: every element (its name is empty)
    std::optional<std::size_t> min_items, max_items;
    const Table& (*table)() = nullptr; // objects: their table (a function: tables may nest)
    std::vector<Type> alternatives;    // any_of: the value is one of these
};

namespace types {
Type number();       // finite
Type positive();     // finite, > 0
Type non_negative(); // finite, >= 0
Type number_in(double lo, double hi);
Type positive_below(double hi); // 0 < x < hi
Type integer(int lo, int hi);
Type boolean();
Type string();
Type one_of(std::vector<std::string> values);
Type pattern(std::string regex); // a string matching it
Type vec3();                     // [x, y, z], finite numbers
// Elements of type `items`, `expected` completing "expected ..." for one element.
Type array_of(Type items, std::string expected, std::size_t min_items = 0);
Type object(const Table& (*table)());
Type map_of(Type values, std::string expected); // an object of any keys, each value of `values`
Type any_of(std::vector<Type> alternatives);
} // namespace types

struct Field {
    std::string name;
    Type type;
    std::string expected; // completes "expected ..."; the schema's description
    bool required = false;
};

struct Table {
    std::string id;          // the schema's $defs name, e.g. "world"
    std::string description; // one line for people and editors
    std::vector<Field> fields;
    const Field& operator[](std::string_view name) const; // std::logic_error if absent
};

// One field's value, read as its table entry says. Each getter throws SceneError at the value's
// JSON path, in the words of the entry's `expected`, when the value does not fit.
class FieldValue {
  public:
    FieldValue(JsonReader reader, const Field& field) : r_(std::move(reader)), f_(&field) {}
    JsonReader& reader() { return r_; }
    const JsonReader& reader() const { return r_; }
    const nlohmann::json& value() const { return r_.value(); }
    [[noreturn]] void fail(const std::string& what) const { r_.fail(what); }

    double number() const; // kNumber: finite and in range
    int integer() const;   // kInteger: in range
    bool boolean() const;
    std::string string() const; // any string (a loader that checks one_of itself, with its words)
    std::string choice() const; // a string in one_of, else "expected one of ..."
    std::array<double, 3> vec3() const;

    // Arrays: the element count, and one element read as the array type's `items` entry says.
    std::size_t size() const; // also checks the type's min_items and max_items
    FieldValue at(std::size_t index) const;

  private:
    JsonReader r_;
    const Field* f_;
};

// An object read through its table: keys outside the table are refused by finish(), with the
// closest field as a suggestion and the table's fields listed.
class ObjectReader {
  public:
    ObjectReader(JsonReader reader, const Table& table); // SceneError unless an object
    bool has(std::string_view name) const;
    FieldValue field(std::string_view name); // SceneError when missing
    std::optional<FieldValue> optional(std::string_view name);
    void finish() const;
    const JsonReader& reader() const { return r_; }
    [[noreturn]] void fail(const std::string& what) const { r_.fail(what); }
    const Table& table() const { return *t_; }

  private:
    JsonReader r_;
    const Table* t_;
};

} // namespace tumble::app
