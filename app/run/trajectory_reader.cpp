#include "app/run/trajectory_reader.h"

#include "app/scene/input_file.h"
#include "app/scene/scene_error.h"

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <string>

namespace tumble::app {
namespace {

// The fields of one CSV line, with where each starts (for messages). A quoted field may hold
// commas and doubled quotes (RFC 4180); lines hold no newlines (names with one are refused).
struct Line {
    std::vector<std::string> fields;
    std::vector<std::size_t> starts; // byte column of each field, 1-based
};

class CsvText {
  public:
    CsvText(std::string text, std::string file) : text_(std::move(text)), file_(std::move(file)) {}

    bool next(Line& line) {
        if (at_ >= text_.size()) return false;
        ++line_no_;
        std::size_t end = text_.find('\n', at_);
        if (end == std::string::npos) end = text_.size();
        split(text_.substr(at_, end - at_), line);
        at_ = end + 1;
        return true;
    }
    // Passes over lines that start with '#'.
    void skip_comments() {
        while (at_ < text_.size() && text_[at_] == '#') {
            const std::size_t end = text_.find('\n', at_);
            at_ = end == std::string::npos ? text_.size() : end + 1;
            ++line_no_;
        }
    }
    [[noreturn]] void fail(std::size_t column, const std::string& what) const {
        throw SceneError(file_, std::to_string(line_no_) + ":" + std::to_string(column), what);
    }

  private:
    void split(const std::string& s, Line& line) {
        line.fields.clear();
        line.starts.clear();
        std::size_t k = 0;
        for (;;) {
            line.starts.push_back(k + 1);
            std::string field;
            if (k < s.size() && s[k] == '"') {
                for (++k;; ++k) {
                    if (k >= s.size()) fail(line.starts.back(), "unterminated quoted field");
                    if (s[k] == '"' && (k + 1 >= s.size() || s[k + 1] != '"')) break;
                    if (s[k] == '"') ++k; // a doubled quote
                    field += s[k];
                }
                ++k;
                if (k < s.size() && s[k] != ',') fail(k + 1, "expected ',' after a quoted field");
            } else {
                const std::size_t comma = s.find(',', k);
                field = s.substr(k, comma == std::string::npos ? std::string::npos : comma - k);
                k = comma == std::string::npos ? s.size() : comma;
            }
            line.fields.push_back(std::move(field));
            if (k >= s.size()) break;
            ++k; // the comma
        }
    }

    std::string text_, file_;
    std::size_t at_ = 0;
    long line_no_ = 0;
};

class Fields {
  public:
    Fields(const CsvText& csv, const Line& line, std::size_t expected) : csv_(csv), line_(line) {
        if (line.fields.size() != expected)
            csv.fail(1, "expected " + std::to_string(expected) + " fields, got " +
                            std::to_string(line.fields.size()));
    }
    double number() {
        const std::string& f = line_.fields[k_];
        char* end = nullptr;
        errno = 0;
        const double x = std::strtod(f.c_str(), &end);
        if (f.empty() || end != f.c_str() + f.size() || errno == ERANGE)
            csv_.fail(line_.starts[k_], "expected a number, got \"" + f.substr(0, 40) + "\"");
        ++k_;
        return x;
    }
    std::int64_t integer() {
        const std::string& f = line_.fields[k_];
        char* end = nullptr;
        errno = 0;
        const long long x = std::strtoll(f.c_str(), &end, 10);
        if (f.empty() || end != f.c_str() + f.size() || errno == ERANGE)
            csv_.fail(line_.starts[k_], "expected an integer, got \"" + f.substr(0, 40) + "\"");
        ++k_;
        return x;
    }
    std::string text() { return line_.fields[k_++]; }
    physics::Vec3 vec3() {
        const double x = number(), y = number(), z = number();
        return {x, y, z};
    }

  private:
    const CsvText& csv_;
    const Line& line_;
    std::size_t k_ = 0;
};

// The header, or with `more` the header followed by columns whose names start with `more` (the
// error estimate's, which the reader skips).
template <class Row, class ParseRow>
std::vector<Row> read_table(const std::filesystem::path& path, const char* header, ParseRow parse,
                            const std::string& more = "") {
    CsvText csv(read_input_file(path, "trajectory"), path.string());
    Line line;
    csv.skip_comments(); // above the header: the scene's record
    if (!csv.next(line)) csv.fail(1, std::string("expected the header line ") + header);
    std::string got;
    for (const std::string& f : line.fields) got += (got.empty() ? "" : ",") + f;
    const std::string base = header;
    const bool extended = !more.empty() && got.starts_with(base + "," + more);
    if (got != header && !extended) csv.fail(1, std::string("expected the header line ") + header);
    const std::size_t columns = line.fields.size();
    std::vector<Row> rows;
    while (csv.next(line)) {
        if (line.fields.size() == 1 && line.fields[0].empty()) continue; // a blank last line
        Fields f(csv, line, columns);
        rows.push_back(parse(f));
    }
    return rows;
}

} // namespace

Trajectory read_trajectory(const std::filesystem::path& states,
                           const std::filesystem::path& diagnostics) {
    Trajectory out;
    out.states = read_table<StateRow>(states, kStatesHeader, [](Fields& f) {
        StateRow r;
        r.step = f.integer();
        r.t = f.number();
        r.body = static_cast<int>(f.integer());
        r.name = f.text();
        r.x = f.vec3();
        const double w = f.number(), x = f.number(), y = f.number(), z = f.number();
        r.q = physics::Quat(w, x, y, z);
        r.v = f.vec3();
        r.w = f.vec3();
        return r;
    });
    if (diagnostics.empty()) return out;
    out.diagnostics = read_diagnostics(diagnostics);
    return out;
}

std::optional<SceneRecord> read_scene_record(const std::filesystem::path& states) {
    std::ifstream in(states, std::ios::binary);
    std::string first;
    if (!in || !std::getline(in, first) || !first.starts_with(kSceneRecordPrefix))
        return std::nullopt;
    const std::string text = first.substr(std::string_view(kSceneRecordPrefix).size());
    const nlohmann::json record = nlohmann::json::parse(text, nullptr, false);
    if (!record.is_object() || !record.contains("source") || !record["source"].is_string() ||
        !record.contains("content_hash") || !record["content_hash"].is_string())
        throw SceneError(states.string(), "1:1",
                         std::string("expected ") + kSceneRecordPrefix +
                             "{\"source\": ..., \"content_hash\": ...}");
    return SceneRecord{record["source"].get<std::string>(),
                       record["content_hash"].get<std::string>()};
}

std::vector<DiagnosticsRow> read_diagnostics(const std::filesystem::path& diagnostics) {
    return read_table<DiagnosticsRow>(
        diagnostics, kDiagnosticsHeader,
        [](Fields& f) {
            DiagnosticsRow r;
            r.step = f.integer();
            r.t = f.number();
            r.kinetic = f.number();
            r.potential = f.number();
            r.energy = f.number();
            r.p = f.vec3();
            r.l = f.vec3();
            return r;
        },
        "err_");
}

} // namespace tumble::app
