#pragma once
// The same scene stepped by several integrators and drawn side by side in one frame, so that what
// each method does to the same motion can be seen frame by frame (a book's flip arriving early or
// late, energy drifting, a spin axis wandering). `tumble render --compare` writes these frames.
//
// Each integrator runs its own Simulation of the scene from the same initial state and time step;
// every frame, each is drawn by one Renderer at the tile's size and copied into its tile of a grid
// (1 x 2 for two, 2 x 2 for up to four, 3 x 2 for six, 3 x 3 for nine), with a dark gutter of
// kGutter pixels between tiles. A tile is exactly the picture `tumble render --integrator NAME`
// draws at the tile's size (tested), so the comparison hides nothing; without the overlay the
// tile is labelled with the method's name in the overlay's corner. A method that diverges stops
// there: its tile keeps the last frame it drew, darkened, and its message is kept; the others go
// on.
#include "app/run/frame_source.h"
#include "app/run/simulation.h"
#include "app/run/timeline.h"
#include "app/scene/scene.h"
#include "render/image.h"
#include "render/renderer.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace tumble::app {

class SideBySide {
  public:
    static constexpr int kGutter = 2; // pixels between tiles

    // One lane per integrator, each a copy of `scene` (whose render settings give the whole
    // frame's size) stepped with `threads` physics threads, for frames first..last. Throws
    // SceneError when the tiles would be smaller than 16 x 16 pixels.
    SideBySide(const Scene& scene, const std::vector<physics::Integrator>& methods,
               const Timeline& tl, int threads, std::int64_t first, std::int64_t last);

    // Steps every lane to its next frame and draws the whole frame into `frame`.
    void draw_next(render::Image& frame);

    struct LaneResult {
        std::string integrator;
        double initial_energy = 0.0, energy = 0.0; // J, when it did not diverge
        std::string diverged;                      // the divergence's message, if it did
        std::vector<std::string> estimate;         // its error estimate's summary, when on
    };
    std::vector<LaneResult> results() const;
    int cols() const { return cols_; }
    int rows() const { return rows_; }
    int tile_width() const { return tile_w_; }
    int tile_height() const { return tile_h_; }

  private:
    struct Lane {
        Scene scene;
        Simulation sim;
        std::unique_ptr<FrameSource> frames;
        render::SceneView view;
        render::Image tile;
        std::string diverged;
    };
    void draw_lane(Lane& lane);

    std::vector<Lane> lanes_;
    int cols_ = 1, rows_ = 1, tile_w_ = 0, tile_h_ = 0;
    std::unique_ptr<render::Renderer> renderer_;
};

} // namespace tumble::app
