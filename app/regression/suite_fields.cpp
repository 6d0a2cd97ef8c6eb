#include "app/regression/suite_fields.h"

#include "app/regression/suite.h"

#include <algorithm>

namespace tumble::app::suite_fields {
namespace {

using namespace types;

// Frames to sample, shared by image and state checks: exactly one of the three is given.
std::vector<Field> sample_fields() {
    return {
        {"frames", array_of(integer(0, 1 << 30), "a frame index", 1),
         "frame indices (frame k shows t = k / fps)"},
        {"every", integer(1, 1 << 30), "a frame step k >= 1: frames 0, k, 2k, ... to the last"},
        {"times", array_of(non_negative(), "a time >= 0 in seconds", 1),
         "times in seconds, each taken at the nearest frame (as render --time does)"},
    };
}

Table with(Table t, std::vector<Field> more) {
    for (Field& f : more) t.fields.push_back(std::move(f));
    return t;
}

Type name_type() {
    return pattern(kNamePattern);
}

} // namespace

bool is_check_name(std::string_view name) {
    // kNamePattern by hand: ASCII letters and digits (the pattern's ranges, whatever the locale),
    // then also '_', '.' and '-'.
    auto alnum = [](char c) {
        return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9');
    };
    if (name.empty() || !alnum(name.front())) return false;
    return std::all_of(name.begin(), name.end(),
                       [&](char c) { return alnum(c) || c == '_' || c == '.' || c == '-'; });
}

const Table& compare() {
    static const Table t{
        "compare",
        "how closely a drawing must match its golden (render/image_compare.h)",
        {{"tolerance", integer(0, 255), "a per-channel tolerance, 0..255"},
         {"perceptual_threshold", number_in(0, 1), "a YIQ threshold in [0, 1]"},
         {"max_different", integer(0, 1 << 30), "a maximum count of differing pixels"},
         {"max_cluster", integer(0, 1 << 30),
          "a maximum size in pixels of a cluster of touching differing pixels"},
         {"detect_antialiasing", boolean(),
          "true or false: count anti-aliased pixels apart (true by default)"}}};
    return t;
}

const Table& image_defaults() {
    static const Table t{
        "image_defaults",
        "what every image check starts from",
        {{"width", integer(RenderSettings::kMinSide, RenderSettings::kMaxWidth),
          "an image width in pixels"},
         {"height", integer(RenderSettings::kMinSide, RenderSettings::kMaxHeight),
          "an image height in pixels"},
         {"overlay", boolean(), "true or false: draw the scene's text overlay"},
         {"compare", object(compare), "how closely a drawing must match its golden"}}};
    return t;
}

const Table& mask() {
    static const Table t{
        "mask",
        "a rectangle of pixels to ignore, from the image's top-left corner",
        {{"x", integer(0, RenderSettings::kMaxWidth), "a left edge in pixels", true},
         {"y", integer(0, RenderSettings::kMaxHeight), "a top edge in pixels", true},
         {"width", integer(1, RenderSettings::kMaxWidth), "a width in pixels", true},
         {"height", integer(1, RenderSettings::kMaxHeight), "a height in pixels", true}}};
    return t;
}

const Table& image() {
    static const Table t =
        with(Table{"image", "an image check: frames drawn and compared with golden PNGs",
                   sample_fields()},
             {{"name", name_type(), "a label added to the checks' names (letters, digits, _ . -)"},
              {"width", image_defaults()["width"].type, "an image width in pixels"},
              {"height", image_defaults()["height"].type, "an image height in pixels"},
              {"overlay", boolean(), "true or false: draw the scene's text overlay"},
              {"compare", object(compare), "how closely a drawing must match its golden"},
              {"masks", array_of(object(mask), "a rectangle {x, y, width, height}"),
               "rectangles of pixels to ignore"}});
    return t;
}

const Table& quantities() {
    static const Table t{
        "quantities",
        "the quantities to compare, each with its absolute tolerance",
        {{"position", non_negative(), "a tolerance >= 0 in metres (distance between positions)"},
         {"orientation", non_negative(),
          "a tolerance >= 0 in radians (angle of the rotation between orientations)"},
         {"velocity", non_negative(), "a tolerance >= 0 in m/s"},
         {"angular_velocity", non_negative(), "a tolerance >= 0 in rad/s"},
         {"energy", non_negative(), "a tolerance >= 0 in joules (the scene's total energy)"},
         {"momentum", non_negative(), "a tolerance >= 0 in kg m/s (the scene's linear momentum)"},
         {"angular_momentum", non_negative(),
          "a tolerance >= 0 in kg m^2/s (the scene's angular momentum about the origin)"}}};
    return t;
}

const Table& state() {
    static const Table t = with(
        Table{"state",
              "a state check: bodies and quantities at frames, compared with a golden trajectory",
              sample_fields()},
        {{"name", name_type(), "a label for the check's name (letters, digits, _ . -)"},
         {"bodies", array_of(string(), "a body's name", 1), "names of the scene's bodies"},
         {"quantities", object(quantities),
          "the quantities to compare, each with its absolute tolerance", true}});
    return t;
}

const Table& scene_entry() {
    static const Table t{
        "scene",
        "a scene and its checks",
        {{"scene", string(),
          "a scene file, relative to the suite's folder (or a built-in scene's name)", true},
         {"name", name_type(), "the prefix of its checks' names (default: the file's stem)"},
         {"images", array_of(object(image), "an image check"), "image checks"},
         {"states", array_of(object(state), "a state check"), "state checks"}}};
    return t;
}

const Table& suite() {
    static const Table t{
        "suite",
        "a Tumble regression suite (docs/regression-testing.md)",
        {{"$schema", string(), "the schema this file follows (for editors; not read)"},
         {"format_version", integer(kSuiteFormatVersion, kSuiteFormatVersion),
          "the suite format version, 1", true},
         {"title", string(), "a title for reports"},
         {"goldens", string(),
          "the folder of the golden files, relative to the suite's folder (default: that "
          "folder)"},
         {"image_defaults", object(image_defaults), "what every image check starts from"},
         {"scenes", array_of(object(scene_entry), "a scene and its checks", 1),
          "scenes and their checks", true}}};
    return t;
}

} // namespace tumble::app::suite_fields
