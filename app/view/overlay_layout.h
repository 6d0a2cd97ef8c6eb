#pragma once
// Where everything drawn over the picture goes (the text overlay, strip charts, legends, a
// comparison tile's label): sized for the frame or tile it is drawn in, in the overlay font's
// units (render/text_overlay.h: overlay_font), and placed in the corner where it hides the least
// of what the picture is about.
//
// What must stay visible is the screen rectangle of every shape but the ground: bodies, arrows,
// the surfaces of a construction (keep_visible). Each panel goes to one of the corners its caller
// allows, in order of preference; a corner that already holds panels stacks the next one beyond
// them (downwards from a top corner, upwards from a bottom one). The corner chosen is the one
// where the panel covers the fewest kept pixels and no other panel; ties go to the preferred
// corner. The layout is made once per run, from the picture at t = 0 (FrameSource), so panels
// never jump about and a still of frame k is frame k of the video.
#include "render/scene_view.h"
#include "render/text_overlay.h"

#include <array>
#include <initializer_list>
#include <vector>

namespace tumble::app {

struct ScreenBox { // pixels from the image's top-left corner
    glm::vec2 min{0.0f}, max{0.0f};
    float area() const;
};
float overlap(const ScreenBox& a, const ScreenBox& b); // area of the intersection

// The screen rectangles of the view's shapes but planes (bodies, arrows, axis rods' bodies) and
// of its translucent surfaces, clipped to a `width` x `height` image; shapes behind the camera
// are left out.
std::vector<ScreenBox> keep_visible(const render::SceneView& view, int width, int height);

enum class Corner : std::uint8_t { TopLeft, TopRight, BottomRight, BottomLeft };

class OverlayLayout {
  public:
    OverlayLayout() = default; // an empty layout: nothing is placed with it
    OverlayLayout(int width, int height, std::vector<ScreenBox> keep);

    int width() const { return width_; }
    int height() const { return height_; }
    const render::OverlayFont& font() const { return font_; }
    // Whether the frame is too small for the full text: a panel `size` would take more than
    // 45% of the width or 35% of the height.
    bool cramped(glm::vec2 size) const;

    // Places a panel of `size` pixels (see the header comment) and returns where it went.
    ScreenBox place(glm::vec2 size, std::initializer_list<Corner> allowed);
    const std::vector<ScreenBox>& placed() const { return placed_; }

  private:
    ScreenBox at_corner(Corner c, glm::vec2 size) const;
    double cost(const ScreenBox& b) const;

    int width_ = 0, height_ = 0;
    render::OverlayFont font_;
    std::vector<ScreenBox> keep_, placed_;
    std::array<float, 4> stacked_{}; // per corner: the height its panels take so far
};

// Legends (what the arrows and a construction's curves are): one line each, a short stroke of
// the item's colour and its name.
struct LegendItem {
    glm::vec4 rgba; // sRGB
    std::string name;
};

// The size of a legend panel of `items` in `font`.
glm::vec2 legend_size(const std::vector<LegendItem>& items, const render::OverlayFont& font);
// Appends the legend's panel, strokes and names to `canvas`, its top-left corner at `at`.
void draw_legend(const std::vector<LegendItem>& items, const render::OverlayFont& font,
                 glm::vec2 at, render::Canvas& canvas);

} // namespace tumble::app
