#include "app/run/side_by_side.h"

#include "app/run/prepare_run.h"
#include "app/run/render_frames.h"
#include "app/scene/scene_error.h"
#include "physics/diagnostics.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace tumble::app {
namespace {

constexpr std::uint8_t kGutterShade = 24; // grey level between tiles

void copy_tile(const render::Image& tile, render::Image& out, int x0, int y0) {
    for (int y = 0; y < tile.height; ++y)
        std::memcpy(out.row(y0 + y) + 3 * x0, tile.row(y), std::size_t(tile.width) * 3);
}

void darken(render::Image& image) {
    for (std::uint8_t& c : image.rgb) c = static_cast<std::uint8_t>(c / 3);
}

} // namespace

SideBySide::SideBySide(const Scene& scene, const std::vector<physics::Integrator>& methods,
                       const Timeline& tl, int threads, std::int64_t first, std::int64_t last) {
    // Columns and rows for n tiles: as square as possible, wider than tall.
    const int n = static_cast<int>(methods.size());
    cols_ = static_cast<int>(std::ceil(std::sqrt(double(n))));
    rows_ = (n + cols_ - 1) / cols_;
    tile_w_ = (scene.render.width - (cols_ - 1) * kGutter) / cols_;
    tile_h_ = (scene.render.height - (rows_ - 1) * kGutter) / rows_;
    if (tile_w_ < 16 || tile_h_ < 16)
        throw SceneError("--compare",
                         std::to_string(tile_w_) + "x" + std::to_string(tile_h_) + " tiles",
                         "too small; give a larger --width/--height");
    lanes_.resize(methods.size());
    for (std::size_t i = 0; i < methods.size(); ++i) {
        lanes_[i].scene = scene;
        lanes_[i].scene.world.integrator = methods[i];
        lanes_[i].sim = start_run(lanes_[i].scene, tl, {threads});
    }
    // One chart scale for every tile: the same value at the same height in each, so one
    // method's drift is seen against another's flat line.
    const auto scale = scene.render.chart.empty()
                           ? nullptr
                           : std::make_shared<ChartScale>(scene.render.chart.size());
    for (Lane& lane : lanes_) // after the resize: FrameSource keeps references
        lane.frames = std::make_unique<FrameSource>(lane.scene, tl, lane.sim, first, last, scale,
                                                    tile_w_, tile_h_);
    RenderSettings tile = scene.render;
    tile.width = tile_w_;
    tile.height = tile_h_;
    renderer_ = std::make_unique<render::Renderer>(render_options(tile));
}

void SideBySide::draw_lane(Lane& lane) {
    if (!lane.diverged.empty()) return;
    try {
        lane.frames->next(lane.view);
        // Without the overlay a tile still says which method it is.
        if (lane.view.overlay.empty())
            lane.view.overlay.assign(
                1, std::string(physics::integrator_info(lane.sim.model.integrator).name));
        renderer_->draw(lane.view, lane.tile);
    } catch (const physics::DivergenceError& e) {
        lane.diverged = e.what();
        if (lane.tile.width == 0) lane.tile = render::Image(tile_w_, tile_h_);
        darken(lane.tile);
    }
}

void SideBySide::draw_next(render::Image& frame) {
    if (frame.width == 0) {
        frame =
            render::Image(lanes_.front().scene.render.width, lanes_.front().scene.render.height);
        std::fill(frame.rgb.begin(), frame.rgb.end(), kGutterShade);
    }
    for (std::size_t i = 0; i < lanes_.size(); ++i) {
        draw_lane(lanes_[i]);
        const int col = int(i) % cols_, row = int(i) / cols_;
        copy_tile(lanes_[i].tile, frame, col * (tile_w_ + kGutter), row * (tile_h_ + kGutter));
    }
}

std::vector<SideBySide::LaneResult> SideBySide::results() const {
    std::vector<LaneResult> out;
    for (const Lane& lane : lanes_) {
        LaneResult r;
        r.integrator = std::string(physics::integrator_info(lane.sim.model.integrator).name);
        r.diverged = lane.diverged;
        r.initial_energy = lane.frames->initial().energy();
        if (r.diverged.empty()) {
            r.energy = physics::diagnose(lane.sim.model, lane.sim.state).energy();
            r.estimate = estimate_summary(lane.sim);
        }
        out.push_back(std::move(r));
    }
    return out;
}

} // namespace tumble::app
