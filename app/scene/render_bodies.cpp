// The bodies that the teaching overlays name (render.chart.body, render.poinsot,
// render.overlay_body and their options), resolved once the scene's bodies are known.
#include "app/scene/body_reference.h"
#include "app/scene/scene.h"
#include "app/scene/scene_error.h"

namespace tumble::app {
namespace {

void resolve(RenderSettings::BodyRef& ref, const std::vector<std::string>& names,
             const std::string& file, const char* purpose) {
    ref.index = ref.name.empty() ? -1 : find_body(names, ref.name, file, ref.place, purpose);
    if (ref.index >= 0) ref.name = names[std::size_t(ref.index)]; // an index becomes the name
}

} // namespace

void resolve_render_bodies(Scene& scene) {
    RenderSettings& rs = scene.render;
    const std::string& file = scene.source;
    std::vector<std::string> names;
    std::vector<bool> dynamic;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        names.push_back(scene.looks[i].name);
        dynamic.push_back(scene.bodies[i].motion == physics::Motion::Dynamic);
    }
    resolve(rs.chart_body, names, file, "chart");
    resolve(rs.poinsot, names, file, "draw Poinsot's construction for");
    resolve(rs.overlay_body, names, file, "show in the overlay");
    auto must_move = [&](const RenderSettings::BodyRef& ref, const char* what) {
        if (ref.index >= 0 && !dynamic[std::size_t(ref.index)])
            throw SceneError(file, ref.place,
                             "body \"" + ref.name + "\" is static: " + what +
                                 " needs one that moves");
    };
    must_move(rs.chart_body, "a chart of one body");
    must_move(rs.poinsot, "Poinsot's construction");
    must_move(rs.overlay_body, "the overlay of one body");
    bool needs_body = false;
    for (Quantity q : rs.chart) needs_body |= !quantity_info(q).of_scene;
    if (needs_body && rs.chart_body.index < 0) {
        // w and w_body are one body's: the first that moves, unless one was named.
        for (std::size_t i = 0; i < dynamic.size() && rs.chart_body.index < 0; ++i)
            if (dynamic[i]) rs.chart_body = {names[i], rs.chart_body.place, int(i)};
        if (rs.chart_body.index < 0)
            throw SceneError(file, "render.chart", "w and w_body need a body that moves");
    }
}

} // namespace tumble::app
