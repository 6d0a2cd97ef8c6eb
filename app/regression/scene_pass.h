#pragma once
// One scene's share of a suite run: a pass over its frames per image size, drawing the frames its
// image checks need and sampling the states its state checks need, with the very steps and views
// `tumble render` uses (app/run/frame_source.h), so frame k here is frame k of the video. The
// automatic camera depends on the picture's aspect, hence one pass per size; the states come from
// the first pass (the physics is the same in every one).
#include "app/regression/check_result.h"

#include <vector>

namespace tumble::app {

struct ScenePass {
    std::vector<render::Image> images; // one per image check asked for, in that order
    std::vector<double> image_seconds; // the time each took to draw
    std::vector<StateOutcome> states;  // one per state check asked for: the samples
    GlIdentity gl;                     // of the renderer that drew (empty if none drew)
};

// Throws what a run throws: physics::DivergenceError, render::RenderError.
ScenePass run_scene_pass(const SuiteScene& scene, const std::vector<const ImageCheck*>& images,
                         const std::vector<const StateCheck*>& states);

} // namespace tumble::app
