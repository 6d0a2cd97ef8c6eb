#include "app/run/render_frames.h"

#include "app/run/frame_source.h"
#include "app/run/progress.h"
#include "io/interrupt.h"

#include <malloc.h>

#include <cstdio>
#include <functional>

namespace tumble::app {

render::RenderOptions render_options(const RenderSettings& rs) {
    render::RenderOptions o;
    o.width = rs.width;
    o.height = rs.height;
    o.samples = rs.antialiasing ? 4 : 1;
    o.shadows = rs.shadows;
    o.soft_shadows = rs.soft_shadows;
    o.ambient_occlusion = rs.ambient_occlusion;
    o.reflections = rs.reflections;
    return o;
}

void tune_allocator_for_rendering() {
    // llvmpipe allocates and frees buffers of a few megabytes per draw call (vertex data for
    // the rasteriser, binned triangles). glibc serves those with fresh mmap()s and returns them
    // at free(), so every frame pays page faults for the same memory again: measured at 10-20%
    // of a frame's CPU time (1000 spheres: 90 ms per frame with these settings, 130-200 without).
    // Serving them from the heap and keeping freed memory there makes the reuse free.
    mallopt(M_MMAP_THRESHOLD, 32 << 20); // the largest glibc accepts
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
}

namespace {

// Frames from `source` through the pipeline into `sink`; `next` fills the next frame's view (false
// when there are none left). Stops early, finishing the frames in flight, on Ctrl-C.
RunResult run_frames(const Scene& scene, std::int64_t count, render::FrameSink& sink, bool quiet,
                     const std::function<bool(render::SceneView&)>& next) {
    tune_allocator_for_rendering();
    RunResult out;
    Progress progress("rendering", count, quiet);
    PipelineStages stages;
    stages.produce = [&](render::SceneView& view) {
        if (io::InterruptGuard::requested()) {
            out.interrupted = true;
            return false;
        }
        return next(view);
    };
    const render::RenderOptions options = render_options(scene.render);
    stages.make_renderer = [options] { return std::make_unique<render::Renderer>(options); };
    stages.consume = [&](const render::Image& image) {
        sink.write(image);
        ++out.frames;
        progress.update(out.frames);
    };
    out.stats = run_pipeline(stages);
    progress.finish();
    return out;
}

} // namespace

RunResult render_frames(const Scene& scene, const Timeline& tl, Simulation& sim,
                        render::FrameSink& sink, std::int64_t first, std::int64_t last, bool quiet,
                        const ResumePoint* resume) {
    FrameSource source(scene, tl, sim, first, last);
    if (resume) source.resume(resume->frame, resume->state);
    return run_frames(scene, last - first + 1, sink, quiet,
                      [&](render::SceneView& view) { return source.next(view); });
}

RunResult render_frames(const Scene& scene, const Timeline& tl, Simulation& sim,
                        render::FrameSink& sink, std::span<const std::int64_t> frames, bool quiet) {
    if (frames.empty()) return {};
    FrameSource source(scene, tl, sim, frames.front(), frames.back());
    std::size_t at = 0;
    return run_frames(scene, std::int64_t(frames.size()), sink, quiet,
                      [&](render::SceneView& view) {
                          if (at == frames.size()) return false;
                          source.skip_to(frames[at++]);
                          return source.next(view);
                      });
}

std::string describe_stats(const PipelineStats& s) {
    char buf[512];
    auto line = [](const char* name, const StageStats& st, char* at, std::size_t size) {
        return std::snprintf(at, size, "  %-8s %6lld frames  %8.3f s busy  %8.1f frames/s\n", name,
                             static_cast<long long>(st.frames), st.busy, st.rate());
    };
    int n = std::snprintf(buf, sizeof buf, "pipeline stages (busy time excludes queue waits):\n");
    n += line("physics", s.physics, buf + n, sizeof buf - std::size_t(n));
    n += line("render", s.render, buf + n, sizeof buf - std::size_t(n));
    n += line("output", s.output, buf + n, sizeof buf - std::size_t(n));
    std::snprintf(buf + n, sizeof buf - std::size_t(n),
                  "  %-8s %6lld frames  %8.3f s wall  %8.1f frames/s  (%.1f ms CPU per frame, all "
                  "threads)\n",
                  "end-to-end", static_cast<long long>(s.frames), s.wall, s.rate(),
                  s.frames > 0 ? 1e3 * s.cpu / double(s.frames) : 0.0);
    return buf;
}

} // namespace tumble::app
