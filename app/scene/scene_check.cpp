#include "app/scene/scene_check.h"

#include "app/scene/json_reader.h"
#include "app/scene/scene_error.h"
#include "physics/build.h"
#include "physics/overlaps.h"

#include <cstdio>
#include <regex>

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
    static const std::regex body(R"(\bbody (\d+)\b)");
    std::string out;
    auto last = what.cbegin();
    for (std::sregex_iterator it(what.begin(), what.end(), body), end; it != end; ++it) {
        const int i = std::stoi((*it)[1].str());
        out.append(last, (*it)[0].first);
        out +=
            i >= 0 && i < int(names.size()) ? body_label(names[std::size_t(i)], i) : (*it)[0].str();
        last = (*it)[0].second;
    }
    out.append(last, what.cend());
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
