// Issue 30, item 1: what is drawn over the picture (the text overlay, strip charts, legends)
// keeps the bodies visible at any size. Measured, not read back from the layout: each frame is
// drawn twice, with and without what is drawn over it (SceneView::overlay and ::canvas), and the
// pixels that differ are the overlays'; the bodies' pixels are those that differ between the
// scene's moving bodies drawn on its ground and the ground alone (no shadows, no ambient
// occlusion, no anti-aliasing, no arrows, trails or constructions). The fraction of body pixels
// covered is summed over frames at a quarter, half and nine tenths of the run, at 320x180 (a tile
// of `render --compare`), 640x360 (slides) and 1280x720.
#include "app/cli/render_setup.h"
#include "app/run/auto_camera.h"
#include "app/run/frame_source.h"
#include "app/run/render_frames.h"
#include "app/run/simulation.h"
#include "app/run/timeline.h"
#include "render/renderer.h"
#include "support/measured.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace tumble::app {
namespace {

struct Coverage {
    long long body = 0, covered = 0;
    double fraction() const { return body > 0 ? double(covered) / double(body) : 0.0; }
};

long long count_differing(const render::Image& a, const render::Image& b,
                          std::vector<bool>* mask = nullptr) {
    long long n = 0;
    for (std::size_t p = 0; p < a.rgb.size() / 3; ++p) {
        const bool differs = a.rgb[3 * p] != b.rgb[3 * p] || a.rgb[3 * p + 1] != b.rgb[3 * p + 1] ||
                             a.rgb[3 * p + 2] != b.rgb[3 * p + 2];
        if (mask) (*mask)[p] = differs;
        n += differs;
    }
    return n;
}

// The bodies alone: each instance of a body (not arrows or rods: body < 0), without axes, on the
// scene's ground; and the ground alone.
void bodies_only(const render::SceneView& view, render::SceneView& with,
                 render::SceneView& without) {
    with = view;
    with.overlay.clear();
    with.canvas.clear();
    with.lines.clear();
    with.glass.clear();
    with.instances.clear();
    without = with;
    for (render::Instance in : view.instances) {
        if (in.body < 0) continue;
        in.axes = false;
        with.instances.push_back(in);
        if (in.mesh == render::MeshKind::Plane) without.instances.push_back(in);
    }
}

Coverage measure(RenderCommand cmd, int width, int height) {
    cmd.width = width, cmd.height = height;
    cmd.common.quiet = true;
    Scene scene = load_for_command(cmd.common);
    apply_render_overrides(cmd, scene);
    const Timeline tl = make_timeline(scene.world.dt, scene.duration, scene.render.fps);
    frame_automatically(scene, tl);
    render::Renderer picture(render_options(scene.render));
    render::RenderOptions plain = render_options(scene.render);
    plain.shadows = plain.ambient_occlusion = plain.reflections = false;
    plain.samples = 1;
    render::Renderer flat(plain);
    Simulation sim = make_simulation(scene, tl.h);
    const std::vector<std::int64_t> frames = {tl.frames / 4, tl.frames / 2, tl.frames * 9 / 10};
    FrameSource source(scene, tl, sim, 0, frames.back());
    render::SceneView view, bare, with, without;
    render::Image a, b, c, d;
    std::vector<bool> over(std::size_t(width) * std::size_t(height)),
        body(std::size_t(width) * std::size_t(height));
    Coverage out;
    for (std::int64_t k = 0; source.next(view); ++k) {
        if (std::find(frames.begin(), frames.end(), k) == frames.end()) continue;
        bare = view;
        bare.overlay.clear();
        bare.canvas.clear();
        picture.draw(view, a);
        picture.draw(bare, b);
        count_differing(a, b, &over);
        bodies_only(view, with, without);
        flat.draw(with, c);
        flat.draw(without, d);
        out.body += count_differing(c, d, &body);
        for (std::size_t p = 0; p < over.size(); ++p) out.covered += over[p] && body[p];
    }
    return out;
}

struct Case {
    const char* name;
    RenderCommand cmd;
};

std::vector<Case> cases() {
    std::vector<Case> out;
    RenderCommand c;
    // The default scene with the overlay: what each tile of `render --compare` shows.
    c.common.scene = "default";
    c.overlay = true;
    out.push_back({"default --overlay", c});
    // ... and with charts (README).
    c.chart = std::vector<std::string>{"energy", "w_body"};
    c.chart_body = "book";
    out.push_back({"default --overlay --chart energy,w_body", c});
    // Lesson 1's video.
    c = RenderCommand();
    c.common.scene = "lessons/wobbling_plate";
    c.vectors = c.axes = true;
    c.trail_axis = "z";
    c.chart = std::vector<std::string>{"w_body", "L"};
    c.chart_body = "plate";
    out.push_back({"lesson 1", c});
    // Lesson 4's video, with the overlay too.
    c = RenderCommand();
    c.common.scene = "lessons/intermediate_axis";
    c.poinsot = "book";
    c.vectors = c.overlay = true;
    c.chart = std::vector<std::string>{"w_body"};
    c.chart_body = "book";
    out.push_back({"lesson 4 --overlay", c});
    return out;
}

TEST(OverlayLayout, OverlaysCoverFewBodyPixelsAtEverySize) {
    double worst = 0.0;
    for (const Case& k : cases()) {
        for (const auto& [w, h] : {std::pair{320, 180}, {640, 360}, {1280, 720}}) {
            const Coverage c = measure(k.cmd, w, h);
            std::printf("[measured] %s at %dx%d: %.4f of %lld body pixels covered\n", k.name, w, h,
                        c.fraction(), c.body);
            ASSERT_GT(c.body, 300) << k.name << " at " << w << "x" << h << ": no bodies seen";
            EXPECT_LE(c.fraction(), 0.02) << k.name << " at " << w << "x" << h;
            worst = std::max(worst, c.fraction());
        }
    }
    TUMBLE_MEASURED(worst, 0.02);
}

} // namespace
} // namespace tumble::app
