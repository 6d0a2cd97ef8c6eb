#pragma once
// The plan of what is drawn over one run's frames (app/view/overlay_layout.h does the placing):
// the text overlay, full or compact, in the corner that hides least (top-left first); the legend
// of the arrows' and the construction's colours (top-right first); one strip chart panel after
// another (bottom-right first, stacking upwards, then the other corners). Made once, from where
// the bodies go on the screen during the run (FrameSource samples it) and the text and legend
// as they are at t = 0, so nothing moves during the run.
#include "app/view/overlay_layout.h"

#include <string>
#include <vector>

namespace tumble::app {

struct OverlayContent {
    // The overlay text at t = 0 in both forms (app/view/overlay_text.h); empty: no overlay.
    std::vector<std::string> text, compact_text;
    std::vector<LegendItem> legend, compact_legend; // empty: no legend
    std::size_t charts = 0;                         // strip chart panels
};

class FrameOverlays {
  public:
    FrameOverlays() = default;
    // Lays out `content` over a `width` x `height` image, keeping clear of `keep` (keep_visible()
    // of the frames of the run: a box seen in many frames weighs as many times).
    FrameOverlays(std::vector<ScreenBox> keep, int width, int height,
                  const OverlayContent& content);

    bool compact_text() const { return compact_text_; }
    glm::vec2 text_at() const { return text_at_; }
    const std::vector<ScreenBox>& charts() const { return charts_; }
    const render::OverlayFont& font() const { return layout_.font(); }
    // The legend's panel into `canvas`, if there is one.
    void draw_legend(render::Canvas& canvas) const;

  private:
    OverlayLayout layout_;
    bool compact_text_ = false, compact_legend_ = false;
    glm::vec2 text_at_{-1.0f, -1.0f};
    std::vector<LegendItem> legend_;
    ScreenBox legend_box_;
    std::vector<ScreenBox> charts_;
};

} // namespace tumble::app
