#pragma once
// Strip charts in the frame (--chart energy,w_body --chart-body book): one panel per quantity,
// time along x (the whole run, or a rolling window), placed by the overlay layout
// (app/view/overlay_layout.h). Each panel has a title with the unit and, for a vector, a legend
// of its x, y and z colours; the y range's ends labelled at the top and bottom of the plot, a
// 0 line when the range spans 0, and the times at both ends of the time axis. The history is
// sampled at every frame time (so a still of frame k shows what frame k of the video shows).
// The y ranges are nice (render/nice_scale.h) and tight: the box holds every sample with less
// than one step of slack at each end (exactly one where the data ends on a step), and changes
// only when a sample leaves it, so the axes do not twitch from frame to frame. With --compare
// the tiles share one ChartScale: the same value sits at the same height in every tile.
#include "app/scene/quantity.h"
#include "app/view/overlay_layout.h"
#include "render/nice_scale.h"
#include "render/scene_view.h"

#include <cstddef>
#include <string>
#include <vector>

namespace tumble::app {

struct ChartSettings {
    std::vector<Quantity> quantities; // one panel each, top to bottom
    int body = -1;                    // the body charted; -1: the scene's sums
    std::string body_name;            // for the titles
    double window = 0.0;              // s of time shown; 0: the whole run
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

// The y range of each panel: the nice range of every sample taken in so far, made again only
// when a sample falls outside it. While the samples vary by less than a millionth of their
// size (a conserved quantity, a component that stays 0) the line is flat, and gets a range of
// its own size around it (render::nice_range).
class ChartScale {
  public:
    explicit ChartScale(std::size_t panels) : panels_(panels) {}
    // Takes in the samples of `history` from `from` on.
    void include(const ChartHistory& history, std::size_t from);
    const render::NiceRange& range(std::size_t panel) const { return panels_[panel].box; }

  private:
    struct Panel {
        double lo = 0.0, hi = 0.0; // of the samples
        bool seen = false, flat = false;
        render::NiceRange box;
    };
    std::vector<Panel> panels_;
};

// The size of one panel in an image of `width` x `height` pixels with `font`.
glm::vec2 chart_panel_size(const render::OverlayFont& font, int width, int height);

// Appends the panels to `canvas`, panel p in boxes[p] (from OverlayLayout::place), for a frame at
// time `now` of a run `duration` long.
void draw_charts(const ChartHistory& history, const ChartScale& scale, double now, double duration,
                 const render::OverlayFont& font, const std::vector<ScreenBox>& boxes,
                 render::Canvas& canvas);

} // namespace tumble::app
