#pragma once
// Strip charts in the frame (--chart energy,w_body --chart-body book): one panel per quantity,
// time along x (the whole run, or a rolling window), stacked in the bottom-right corner, with
// a title, units and the ends of both axes. The history is sampled at every frame time (so a
// still of frame k shows what frame k of the video shows), and the y ranges only ever grow, in
// steps of 1, 2 or 5 x 10^k, so the axes do not twitch from frame to frame. With --compare the
// tiles share one ChartScale: the same value sits at the same height in every tile.
#include "app/scene/chart_quantity.h"
#include "render/scene_view.h"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace tumble::app {

struct ChartSettings {
    std::vector<ChartQuantity> quantities; // one panel each, top to bottom
    int body = -1;                         // the body charted; -1: the scene's sums
    std::string body_name;                 // for the titles
    double window = 0.0;                   // s of time shown; 0: the whole run
};

// Every charted quantity at every frame time so far.
class ChartHistory {
  public:
    ChartHistory(const ChartSettings& settings, const physics::Model& model,
                 const physics::State& initial); // records the first sample
    void record(const physics::Model& model, const physics::State& state);

    std::size_t samples() const { return times_.size(); }
    std::size_t panels() const { return settings_.quantities.size(); }
    double time(std::size_t k) const { return times_[k]; }
    double value(std::size_t panel, int component, std::size_t k) const {
        return values_[(k * panels() + panel) * 3 + std::size_t(component)];
    }
    const ChartSettings& settings() const { return settings_; }

  private:
    ChartSettings settings_;
    double e0_ = 0.0;
    std::vector<double> times_;
    std::vector<double> values_; // [sample][panel][3]
};

// The y range of each panel: grows to hold every sample it is shown, never shrinks.
class ChartScale {
  public:
    explicit ChartScale(std::size_t panels) : ranges_(panels, {0.0, 0.0}), seen_(panels, false) {}
    // Takes in the samples of `history` from `from` on.
    void include(const ChartHistory& history, std::size_t from);
    std::pair<double, double> range(std::size_t panel) const { return ranges_[panel]; }

  private:
    std::vector<std::pair<double, double>> ranges_;
    std::vector<bool> seen_;
};

// "Nice" bounds holding [lo, hi]: rounded out to a multiple of a step of 1, 2 or 5 x 10^k, about
// a fifth of the span (a flat line gets a span of its own size, or 1e-12 around 0).
std::pair<double, double> nice_range(double lo, double hi);

// Appends the panels to `canvas`, for a frame at time `now` of a run `duration` long, in an image
// of `width` x `height` pixels.
void draw_charts(const ChartHistory& history, const ChartScale& scale, double now, double duration,
                 int width, int height, render::Canvas& canvas);

} // namespace tumble::app
