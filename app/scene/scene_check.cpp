#include "app/scene/scene_check.h"

#include "app/scene/json_reader.h"
#include "app/scene/scene_error.h"
#include "physics/build.h"
#include "physics/overlaps.h"

#include <cstdio>
#include <string_view>

namespace tumble::app {
namespace {

// Where a physics field lives in the scene format, below /bodies/i or /world.
std::string json_field(const std::string& field) {
    if (field == "radius" || field == "size" || field == "length" || field == "file")
        return "shape/" + field;
    if (field == "friction" || field == "restitution") return "material/" + field;
    return field;
}

// `body 3 "left wall"`; a long name cut to an excerpt (describe_json), so that no message quotes a
// whole value.
std::string body_label(const std::string& name, int i) {
    return "body " + std::to_string(i) + " " + describe_json(name);
}

std::vector<std::string> body_names(const Scene& scene) {
    std::vector<std::string> out;
    for (const BodyLook& look : scene.looks) out.push_back(look.name);
    return out;
}

} // namespace

std::string with_body_names(const std::vector<std::string>& names, const std::string& what) {
    // Each "body N" that stands as words of its own (no letter, digit or '_' just before "body"
    // or just after N), the regular expression \bbody (\d+)\b scanned by hand: <regex> alone
    // cost this library's build 3 s.
    auto digit = [](char c) { return c >= '0' && c <= '9'; };
    auto word = [&](char c) {
        return digit(c) || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
    };
    static constexpr std::string_view kBody = "body ";
    std::string out;
    std::size_t copied = 0;
    for (std::size_t at = what.find(kBody); at != std::string::npos;
         at = what.find(kBody, at + 1)) {
        const std::size_t first = at + kBody.size();
        std::size_t end = first;
        while (end < what.size() && digit(what[end])) ++end;
        if (end == first || (at > 0 && word(what[at - 1])) ||
            (end < what.size() && word(what[end])))
            continue;
        // Nine digits or fewer fit an int; a longer number is no body of the scene either way.
        const std::size_t i =
            end - first < 10 ? std::stoul(what.substr(first, end - first)) : names.size();
        out.append(what, copied, at - copied);
        out += i < names.size() ? body_label(names[i], int(i)) : what.substr(at, end - at);
        copied = end;
        at = end - 1;
    }
    out.append(what, copied);
    return out;
}

CheckedStart build_checked(const Scene& scene, double dt) {
    physics::WorldDef world = scene.world;
    world.dt = dt;
    try {
        CheckedStart start{physics::build_model(world, scene.bodies), {}};
        start.state = physics::initial_state(start.model, scene.bodies);
        return start;
    } catch (const physics::ModelError& e) {
        const std::string field = json_field(e.field);
        const std::string place =
            e.body < 0 ? "/world/" + field : "/bodies/" + std::to_string(e.body) + "/" + field;
        throw SceneError(scene.source, place, with_body_names(body_names(scene), e.what()));
    }
}

std::vector<std::string> initial_state_warnings(const Scene& scene, const physics::Model& model,
                                                const physics::State& state) {
    std::vector<std::string> out;
    if (!model.passes.contacts) return out;
    for (const physics::Overlap& o : physics::deep_initial_overlaps(model, state)) {
        char numbers[96];
        std::snprintf(numbers, sizeof numbers,
                      " by %.1f mm; contacts will push them apart at up "
                      "to %.3g m/s",
                      o.depth * 1000.0, model.contact.max_push_speed);
        out.push_back(scene.source + ": /bodies/" + std::to_string(o.b) +
                      "/position: " + body_label(scene.looks[std::size_t(o.b)].name, o.b) +
                      " starts interpenetrating " +
                      body_label(scene.looks[std::size_t(o.a)].name, o.a) + numbers +
                      " (move them apart if not intended)");
    }
    return out;
}

} // namespace tumble::app
