#include "app/run/timeline.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tumble::app {

Timeline make_timeline(double scene_dt, double duration, int fps) {
    Timeline t;
    t.fps = fps;
    t.scene_dt = scene_dt;
    const double interval = 1.0 / fps;
    // The 1e-9 slack keeps dt = 1/240 at 60 fps to exactly 4 steps despite rounding in 1/240.
    t.steps_per_frame = std::max(1, static_cast<int>(std::ceil(interval / scene_dt - 1e-9)));
    t.h = 1.0 / (static_cast<double>(fps) * t.steps_per_frame);
    t.frames = std::max<std::int64_t>(1, std::llround(duration * fps));
    return t;
}

std::string Timeline::describe() const {
    char buf[256];
    std::snprintf(buf, sizeof buf, "%lld frames at %d fps, %d step%s of %.9g s per frame%s",
                  static_cast<long long>(frames), fps, steps_per_frame,
                  steps_per_frame == 1 ? "" : "s", h,
                  adjusted() ? " (scene dt adjusted down so that steps land on frame times)" : "");
    return buf;
}

std::string Timeline::adjustment_note() const {
    if (!adjusted()) return "";
    char buf[256];
    std::snprintf(
        buf, sizeof buf,
        "dt %.9g s lowered to %.9g s so that %d step%s land%s on each frame time (%d fps)",
        scene_dt, h, steps_per_frame, steps_per_frame == 1 ? "" : "s",
        steps_per_frame == 1 ? "s" : "", fps);
    return buf;
}

} // namespace tumble::app
