#pragma once
// When frames are taken. Frame k shows the state at exactly t_k = k / fps: the physics step is
// chosen so that a whole number of steps fits in one frame interval,
//   steps_per_frame = ceil((1/fps) / dt_scene),   h = 1 / (fps * steps_per_frame) <= dt_scene,
// and frame k is taken after k * steps_per_frame steps, so t_k = k * steps_per_frame * h has one
// rounding and no drift. When h differs from the scene's dt the run says so (never silently).
#include <cstdint>
#include <string>

namespace tumble::app {

struct Timeline {
    int fps = 60;
    int steps_per_frame = 1;
    double h = 0.0;          // the step actually used, s
    double scene_dt = 0.0;   // the step the scene asked for, s
    std::int64_t frames = 0; // frame 0 at t = 0 .. frame frames-1 at t = (frames-1)/fps

    bool adjusted() const { return h != scene_dt; }
    double frame_time(std::int64_t k) const { return static_cast<double>(k) / fps; }
    // Steps to the last frame, t = (frames - 1) / fps: what a video draws.
    std::int64_t total_steps() const { return (frames - 1) * steps_per_frame; }
    // Steps to t = frames / fps, the end of the video's last frame interval: where `simulate`
    // ends, so a trajectory of `duration` seconds reaches t = duration (when duration * fps is
    // whole; else the nearest frame time, as the video's own length).
    std::int64_t end_step() const { return frames * steps_per_frame; }
    std::string describe() const; // one line for summaries and `tumble explain`
    // When adjusted(): "dt 0.001 s lowered to 0.000980392157 s so that 17 steps land on each
    // frame time (60 fps)"; else empty. Every command that steps a scene prints it.
    std::string adjustment_note() const;
};

// frames = round(duration * fps), at least 1: a 10 s clip at 60 fps has 600 frames and lasts
// exactly 10 s in the container.
Timeline make_timeline(double scene_dt, double duration, int fps);

} // namespace tumble::app
