#include "app/regression/scene_pass.h"

#include "app/run/auto_camera.h"
#include "app/run/frame_source.h"
#include "app/run/prepare_run.h"
#include "app/run/render_frames.h"
#include "io/interrupt.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>
#include <optional>

namespace tumble::app {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The states of `checks` at `frame`, if it is one of theirs.
void sample(const std::vector<const StateCheck*>& checks, std::int64_t frame, const Simulation& sim,
            const Scene& scene, std::vector<StateOutcome>& out) {
    std::optional<DiagnosticsRow> diagnostics;
    for (std::size_t c = 0; c < checks.size(); ++c) {
        const StateCheck& check = *checks[c];
        if (!std::binary_search(check.frames.begin(), check.frames.end(), frame)) continue;
        if (!diagnostics) diagnostics = diagnostics_row(sim.model, sim.state);
        Sample s;
        s.frame = frame;
        s.diagnostics = *diagnostics;
        for (int b : check.body_indices)
            s.bodies.push_back(state_row(sim.model, sim.state, b, scene.looks[b].name));
        out[c].samples.push_back(std::move(s));
    }
}

using Size = std::pair<int, int>;

// One pass at one size: draws the frames of `indices` (into images asked for by `images`) and,
// when `states` is not empty, samples them.
void pass(const SuiteScene& s, Size size, const std::vector<const ImageCheck*>& images,
          const std::vector<std::size_t>& indices, const std::vector<const StateCheck*>& states,
          ScenePass& out) {
    Scene scene = s.scene;
    scene.render.width = size.first;
    scene.render.height = size.second;
    // The overlay when a check wants it (each check clears the overlay it does not want); not
    // for nothing, since the overlays' layout then looks at the whole run (FrameSource).
    scene.render.overlay = std::any_of(indices.begin(), indices.end(),
                                       [&](std::size_t i) { return images[i]->overlay; });
    std::int64_t last = 0;
    for (std::size_t i : indices) last = std::max(last, images[i]->frame);
    for (const StateCheck* c : states) last = std::max(last, c->frames.back());
    std::unique_ptr<render::Renderer> renderer;
    if (!indices.empty()) {
        frame_automatically(scene, s.timeline); // the still of frame k is frame k of the video
        renderer = std::make_unique<render::Renderer>(render_options(scene.render));
        out.gl = {renderer->gl_renderer(), renderer->gl_version()};
    }
    Simulation sim = start_run(scene, s.timeline, {1, false});
    FrameSource frames(scene, s.timeline, sim, 0, last);
    frames.observe([&](std::int64_t k, const Simulation& at) {
        if (!states.empty()) sample(states, k, at, scene, out.states);
    });
    render::SceneView view;
    for (std::int64_t k = 0; frames.next(view); ++k) {
        io::InterruptGuard::stop_if_requested("a suite's scene pass");
        for (std::size_t i : indices) {
            if (images[i]->frame != k) continue;
            const auto start = std::chrono::steady_clock::now();
            std::vector<std::string> overlay;
            if (!images[i]->overlay) overlay.swap(view.overlay);
            renderer->draw(view, out.images[i]);
            if (!images[i]->overlay) overlay.swap(view.overlay);
            out.image_seconds[i] = seconds_since(start);
        }
    }
}

} // namespace

ScenePass run_scene_pass(const SuiteScene& s, const std::vector<const ImageCheck*>& images,
                         const std::vector<const StateCheck*>& states) {
    ScenePass out;
    out.images.resize(images.size());
    out.image_seconds.resize(images.size());
    out.states.resize(states.size());
    std::map<Size, std::vector<std::size_t>> by_size; // ordered: the same passes every run
    for (std::size_t i = 0; i < images.size(); ++i)
        by_size[{images[i]->width, images[i]->height}].push_back(i);
    bool sampled = states.empty();
    for (const auto& [size, indices] : by_size) {
        pass(s, size, images, indices, sampled ? std::vector<const StateCheck*>{} : states, out);
        sampled = true;
    }
    if (!sampled) pass(s, {s.scene.render.width, s.scene.render.height}, images, {}, states, out);
    return out;
}

} // namespace tumble::app
