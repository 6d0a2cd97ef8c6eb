#include "app/scene/json_duplicate_keys.h"

#include "app/scene/json_reader.h"

#include <map>
#include <vector>

namespace tumble::app {
namespace {

// One open object or array, and where the scanner is in it.
struct Level {
    bool object = false;
    std::map<std::string, std::string> keys; // key -> "line:column" of its first appearance
    std::string segment;                     // the current key (objects) or index (arrays)
    std::size_t index = 0;                   // the current element (arrays)
    bool expect_key = false;                 // the next string is a key (objects)
};

class Scanner {
  public:
    Scanner(const std::string& text, const std::string& file) : text_(text), file_(file) {}

    void run() {
        while (at_ < text_.size()) {
            const char c = text_[at_];
            if (c == '"') {
                string_token();
            } else {
                punctuation(c);
                advance();
            }
        }
    }

  private:
    void advance() {
        if (text_[at_++] == '\n')
            ++line_, column_ = 1;
        else
            ++column_;
    }

    void punctuation(char c) {
        if (c == '{' || c == '[') {
            levels_.push_back(Level{c == '{', {}, c == '{' ? "" : "0", 0, c == '{'});
        } else if ((c == '}' || c == ']') && !levels_.empty()) {
            levels_.pop_back();
        } else if (c == ',' && !levels_.empty()) {
            Level& l = levels_.back();
            if (l.object)
                l.expect_key = true;
            else
                l.segment = std::to_string(++l.index);
        }
    }

    // A string from its opening quote to its closing one; a key if an object expects one.
    void string_token() {
        const std::string place = std::to_string(line_) + ":" + std::to_string(column_);
        const std::size_t begin = at_;
        advance();
        while (text_[at_] != '"') {
            if (text_[at_] == '\\') advance();
            advance();
        }
        advance();
        if (levels_.empty() || !levels_.back().expect_key) return;
        const std::string raw = text_.substr(begin, at_ - begin);
        key(raw.find('\\') == std::string::npos ? raw.substr(1, raw.size() - 2)
                                                : nlohmann::json::parse(raw).get<std::string>(),
            place);
    }

    void key(const std::string& k, const std::string& place) {
        Level& l = levels_.back();
        l.expect_key = false;
        l.segment = json_pointer_segment(k);
        const auto [first, inserted] = l.keys.emplace(k, place);
        if (inserted) return;
        std::string path;
        for (const Level& level : levels_) path += "/" + level.segment;
        throw SceneError(file_, path,
                         "duplicate key " + describe_json(k) + ": first at " + first->second +
                             ", again at " + place + " (a key may appear once in an object)");
    }

    const std::string& text_;
    const std::string& file_;
    std::size_t at_ = 0, line_ = 1, column_ = 1;
    std::vector<Level> levels_;
};

} // namespace

void check_duplicate_keys(const std::string& text, const std::string& file) {
    Scanner(text, file).run();
}

} // namespace tumble::app
