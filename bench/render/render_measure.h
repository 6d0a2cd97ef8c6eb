#pragma once
// One case of the render benchmark measured: `repeats` runs into its real sink (MP4, PNG frames or
// GIF), each followed by one into the null sink (same binary, same frames, interleaved so that a
// busy spell on the machine hits both alike). Medians per pipeline stage (app/run/pipeline.h) and
// end to end; the ratio of the two end-to-end rates says what the output costs beyond drawing.
#include "bench/render/render_cases.h"

#include <filesystem>

namespace tumble::bench {

struct RenderRow {
    const RenderCase* c;
    int frames, repeats;
    // Frames per second: each stage's over its busy time (queue waits excluded), end to end over
    // the run's wall time including the sink's finish (the encoder's last frames, a GIF's
    // palette passes).
    double physics, render, output, e2e, null_render, null_e2e;
    double cpu_ms, null_cpu_ms; // process CPU time per frame, every thread
    double ratio() const { return e2e > 0 ? null_e2e / e2e : 0.0; }
};

// Runs the case `repeats` times each way (its `quick_frames` when `quick`), writing the real
// outputs under `scratch` (emptied before each run); says each run's rates on stderr.
RenderRow measure(const RenderCase& c, int repeats, bool quick,
                  const std::filesystem::path& scratch);

double median(std::vector<double> v);

} // namespace tumble::bench
