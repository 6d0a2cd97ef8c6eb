#include "app/scene/json_nesting.h"

#include "app/scene/scene_error.h"
#include "app/scene/text_place.h"

namespace tumble::app {

void check_json_nesting(const std::string& text, const std::string& file) {
    int depth = 0;
    bool in_string = false;
    for (std::size_t k = 0; k < text.size(); ++k) {
        const char c = text[k];
        if (in_string) {
            if (c == '\\')
                ++k; // the escaped character, whatever it is, does not end the string
            else if (c == '"')
                in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonDepth)
                throw SceneError(file, line_column(text, k),
                                 "arrays and objects nested deeper than " +
                                     std::to_string(kMaxJsonDepth) +
                                     " levels (a scene needs about 8)");
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
}

} // namespace tumble::app
