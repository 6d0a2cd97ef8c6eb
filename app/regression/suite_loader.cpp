// Suite file -> Suite, read through the suite's field tables (app/regression/suite_fields.h).
#include "app/regression/suite.h"
#include "app/regression/suite_fields.h"

#include "app/run/prepare_run.h"
#include "app/run/trajectory_writer.h"
#include "app/scene/input_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

namespace tumble::app {
namespace {

namespace fields = suite_fields;

struct Context {
    std::filesystem::path folder;             // the suite's
    std::filesystem::path goldens;            // golden files
    std::map<std::string, std::string> names; // check name -> where it was declared
    // Anti-aliasing-aware by default: channel noise up to 2 and changes a viewer would barely
    // see (YIQ 0.05) are no change, edge pixels are counted apart, and no other pixel may differ.
    render::CompareOptions compare{2, 0.05, 0, true};
    int width = 320, height = 180;
    bool overlay = false;
};

render::CompareOptions read_compare(ObjectReader r, render::CompareOptions c) {
    if (auto v = r.optional("tolerance")) c.tolerance = v->integer();
    if (auto v = r.optional("perceptual_threshold")) c.perceptual_threshold = v->number();
    if (auto v = r.optional("max_different")) c.max_different = v->integer();
    if (auto v = r.optional("max_cluster")) c.max_cluster = v->integer();
    if (auto v = r.optional("detect_antialiasing")) c.detect_antialiasing = v->boolean();
    r.finish();
    return c;
}

std::string frames_note(const Timeline& tl, double duration) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "the scene has %lld frames: %g s at %d fps",
                  static_cast<long long>(tl.frames), duration, tl.fps);
    return buf;
}

// The frames an entry samples: exactly one of "frames", "every" and "times".
std::vector<std::int64_t> read_frames(ObjectReader& r, const SuiteScene& s) {
    const Timeline& tl = s.timeline;
    const int given = int(r.has("frames")) + int(r.has("every")) + int(r.has("times"));
    if (given != 1) r.fail("give exactly one of \"frames\", \"every\" and \"times\"");
    const std::string last = std::to_string(tl.frames - 1);
    std::vector<std::int64_t> out;
    if (auto f = r.optional("frames")) {
        for (std::size_t i = 0; i < f->size(); ++i) {
            const std::int64_t k = f->at(i).integer();
            if (k >= tl.frames)
                f->at(i).fail("expected a frame index in [0, " + last + "] (" +
                              frames_note(tl, s.scene.duration) + ")");
            out.push_back(k);
        }
    } else if (auto e = r.optional("every")) {
        for (std::int64_t k = 0, step = e->integer(); k < tl.frames; k += step) out.push_back(k);
    } else if (auto t = r.optional("times")) {
        for (std::size_t i = 0; i < t->size(); ++i) {
            const double seconds = t->at(i).number();
            const auto k = static_cast<std::int64_t>(std::llround(seconds * tl.fps));
            if (k >= tl.frames)
                t->at(i).fail("expected a time at most " +
                              std::to_string(tl.frame_time(tl.frames - 1)) + " s, frame " + last +
                              " (" + frames_note(tl, s.scene.duration) + ")");
            out.push_back(k);
        }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

// A "name" field's value: letters, digits, '_', '.' and '-' (fields::kNamePattern), as it becomes
// part of a golden's file name: no '/' that would put the golden in another folder.
std::string check_name(const FieldValue& v) {
    std::string name = v.string();
    if (!fields::is_check_name(name))
        v.fail("expected a name of letters, digits, '_', '.' and '-' (starting with a letter or "
               "digit), got " +
               describe_json(v.value()));
    return name;
}

void claim_name(Context& c, const JsonReader& at, const std::string& name) {
    const auto [it, fresh] = c.names.emplace(name, at.path());
    if (!fresh)
        at.fail("two checks are named " + name + " (the other is at " + it->second +
                "); give one of them a \"name\"");
}

std::string frame_digits(std::int64_t k) {
    char digits[32];
    std::snprintf(digits, sizeof digits, "%04lld", static_cast<long long>(k));
    return digits;
}

Mask read_mask(ObjectReader r, int width, int height) {
    Mask m{r.field("x").integer(), r.field("y").integer(), r.field("width").integer(),
           r.field("height").integer()};
    if (m.x + m.width > width || m.y + m.height > height)
        r.fail("expected a rectangle inside the " + std::to_string(width) + "x" +
               std::to_string(height) + " image");
    r.finish();
    return m;
}

void read_image(ObjectReader r, SuiteScene& s, Context& c) {
    ImageCheck base;
    base.width = c.width, base.height = c.height, base.overlay = c.overlay;
    base.compare = c.compare;
    base.where = r.reader().path();
    if (auto v = r.optional("width")) base.width = v->integer();
    if (auto v = r.optional("height")) base.height = v->integer();
    if (auto v = r.optional("overlay")) base.overlay = v->boolean();
    if (auto v = r.optional("compare"))
        base.compare = read_compare(ObjectReader(v->reader(), fields::compare()), c.compare);
    if (auto v = r.optional("masks"))
        for (std::size_t i = 0; i < v->size(); ++i)
            base.masks.push_back(read_mask(ObjectReader(v->at(i).reader(), fields::mask()),
                                           base.width, base.height));
    std::string label = base.overlay ? "_overlay" : "";
    if (auto v = r.optional("name")) label = "_" + check_name(*v);
    for (std::int64_t k : read_frames(r, s)) {
        ImageCheck check = base;
        check.frame = k;
        check.name = s.name + "_" + frame_digits(k) + label;
        check.golden = c.goldens / (check.name + ".png");
        claim_name(c, r.reader(), check.name);
        s.images.push_back(check);
    }
    r.finish();
}

// The scene's body called `name`, by index; SceneError at `at` naming the scene's bodies.
int find_body(const FieldValue& at, const Scene& scene, const std::string& name) {
    std::string known;
    int found = -1;
    for (std::size_t i = 0; i < scene.looks.size(); ++i) {
        if (scene.looks[i].name == name && found >= 0)
            at.fail("bodies " + std::to_string(found) + " and " + std::to_string(i) + " of " +
                    scene.source + " are both named " + describe_json(name) +
                    ": give them names of their own");
        if (scene.looks[i].name == name) found = static_cast<int>(i);
        if (i < 8) known += (i ? ", " : "") + scene.looks[i].name;
    }
    if (found >= 0) return found;
    if (scene.looks.size() > 8) known += ", ... (" + std::to_string(scene.looks.size()) + ")";
    at.fail("no body named " + describe_json(name) + " in " + scene.source + " (bodies: " + known +
            ")");
}

std::vector<Tolerance> read_quantities(ObjectReader r) {
    std::vector<Tolerance> out;
    for (int q = 0; q <= int(StateQuantity::kAngularMomentum); ++q)
        if (auto v = r.optional(quantity_name(StateQuantity(q))))
            out.push_back({StateQuantity(q), v->number()});
    r.finish();
    if (out.empty()) r.fail("expected at least one quantity with its tolerance");
    return out;
}

void read_bodies(ObjectReader& r, const Scene& scene, StateCheck& check) {
    const bool body_quantity = std::any_of(check.quantities.begin(), check.quantities.end(),
                                           [](const Tolerance& t) { return per_body(t.quantity); });
    auto bodies = r.optional("bodies");
    if (body_quantity && !bodies)
        r.fail("position, orientation, velocity and angular_velocity are per body: give "
               "\"bodies\"");
    if (!bodies) return;
    if (!body_quantity)
        bodies->fail("no per-body quantity (position, orientation, velocity, angular_velocity) "
                     "is checked for these bodies");
    for (std::size_t i = 0; i < bodies->size(); ++i) {
        const std::string name = bodies->at(i).string();
        if (std::find(check.bodies.begin(), check.bodies.end(), name) != check.bodies.end())
            bodies->at(i).fail("body " + describe_json(name) + " is listed twice");
        check.body_indices.push_back(find_body(bodies->at(i), scene, name));
        check.bodies.push_back(name);
    }
}

void read_state(ObjectReader r, SuiteScene& s, Context& c) {
    StateCheck check;
    check.where = r.reader().path();
    check.quantities =
        read_quantities(ObjectReader(r.field("quantities").reader(), fields::quantities()));
    read_bodies(r, s.scene, check);
    check.frames = read_frames(r, s);
    check.name = s.name + "_" + (r.has("name") ? check_name(r.field("name")) : "states");
    check.golden = c.goldens / (check.name + ".csv");
    claim_name(c, r.reader(), check.name);
    r.finish();
    s.states.push_back(std::move(check));
}

// A scene path relative to the suite's folder, else a built-in scene's name ("default",
// "lessons/heavy_top": `tumble scenes` lists them).
Scene load_entry_scene(const FieldValue& v, const Context& c) {
    const std::string arg = v.string();
    std::error_code ec;
    const std::filesystem::path local = c.folder / arg;
    if (std::filesystem::exists(local, ec)) return load_scene_argument(local.string());
    const std::vector<std::string> builtins = builtin_scene_names();
    const std::string stem = arg.ends_with(".json") ? arg.substr(0, arg.size() - 5) : arg;
    if (std::find(builtins.begin(), builtins.end(), stem) != builtins.end())
        return load_scene_argument("builtin:" + arg); // never a file of that name elsewhere
    if (arg.find('/') != std::string::npos) return load_scene_argument(local.string());
    v.fail("no scene file " + local.string() + " and no built-in scene " + describe_json(arg));
}

SuiteScene read_scene_entry(ObjectReader r, Context& c) {
    SuiteScene s;
    const FieldValue scene = r.field("scene");
    s.argument = scene.string();
    // As every command runs it (app/run/prepare_run.h): "auto" resolved for the scene's frame
    // rate, so the goldens record the trajectory `tumble simulate` and `tumble render` produce.
    RunPlan plan = plan_run(load_entry_scene(scene, c));
    s.scene = std::move(plan.scene);
    s.timeline = plan.timeline;
    if (auto n = r.optional("name")) {
        s.name = check_name(*n);
    } else {
        s.name = scene_name(s.scene);
        if (!fields::is_check_name(s.name))
            scene.fail("the file's stem \"" + s.name + "\" cannot name checks; give a \"name\"");
    }
    if (auto images = r.optional("images"))
        for (std::size_t i = 0; i < images->size(); ++i)
            read_image(ObjectReader(images->at(i).reader(), fields::image()), s, c);
    if (auto states = r.optional("states"))
        for (std::size_t i = 0; i < states->size(); ++i)
            read_state(ObjectReader(states->at(i).reader(), fields::state()), s, c);
    r.finish();
    if (s.images.empty() && s.states.empty()) r.fail("expected \"images\" or \"states\" checks");
    return s;
}

void read_image_defaults(ObjectReader r, Context& c) {
    if (auto v = r.optional("width")) c.width = v->integer();
    if (auto v = r.optional("height")) c.height = v->integer();
    if (auto v = r.optional("overlay")) c.overlay = v->boolean();
    if (auto v = r.optional("compare"))
        c.compare = read_compare(ObjectReader(v->reader(), fields::compare()), c.compare);
    r.finish();
}

} // namespace

const char* quantity_name(StateQuantity q) {
    static const char* const names[] = {"position",         "orientation", "velocity",
                                        "angular_velocity", "energy",      "momentum",
                                        "angular_momentum"};
    return names[int(q)];
}

const char* quantity_unit(StateQuantity q) {
    static const char* const units[] = {"m", "rad", "m/s", "rad/s", "J", "kg m/s", "kg m^2/s"};
    return units[int(q)];
}

bool per_body(StateQuantity q) {
    return q <= StateQuantity::kAngularVelocity;
}

std::filesystem::path StateCheck::golden_diagnostics() const {
    return diagnostics_path_for(golden.string());
}

std::size_t Suite::check_count() const {
    std::size_t n = 0;
    for (const SuiteScene& s : scenes) n += s.images.size() + s.states.size();
    return n;
}

Suite load_suite(const std::filesystem::path& path) {
    const nlohmann::json root = parse_json(read_input_file(path, "suite"), path.string());
    ObjectReader r(JsonReader(root, path.string(), ""), fields::suite());
    if (root.contains("bodies") && !root.contains("scenes"))
        r.fail("this is a scene file, not a suite: a suite lists \"scenes\" and their checks "
               "(docs/regression-testing.md)");
    const FieldValue version = r.field("format_version");
    // Read wider than the table's [1, 1], to say which version this tumble reads.
    const int given = version.reader().integer(1, 1000, "the suite format version");
    if (given != kSuiteFormatVersion)
        version.fail("this tumble reads suite format_version " +
                     std::to_string(kSuiteFormatVersion) + ", got " + std::to_string(given));
    Suite suite;
    suite.path = path;
    Context c;
    c.folder = path.parent_path();
    c.goldens = c.folder;
    if (auto g = r.optional("goldens")) c.goldens = c.folder / g->string();
    suite.goldens = c.goldens;
    if (auto t = r.optional("title")) suite.title = t->string();
    if (auto d = r.optional("image_defaults"))
        read_image_defaults(ObjectReader(d->reader(), fields::image_defaults()), c);
    const FieldValue scenes = r.field("scenes");
    for (std::size_t i = 0; i < scenes.size(); ++i)
        suite.scenes.push_back(
            read_scene_entry(ObjectReader(scenes.at(i).reader(), fields::scene_entry()), c));
    r.finish();
    return suite;
}

} // namespace tumble::app
