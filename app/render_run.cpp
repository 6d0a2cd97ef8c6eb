#include "app/render_run.h"

#include "app/frame_source.h"
#include "app/interrupt.h"
#include "app/progress.h"
#include "app/scene_error.h"

#include <malloc.h>

#include <filesystem>

#include <cstdio>

namespace tumble::app {

void apply_render_overrides(const RenderCommand& cmd, Scene& scene) {
    RenderSettings& rs = scene.render;
    if (cmd.preview) { // a quick look: small, no shadows, no anti-aliasing
        rs.width = 640;
        rs.height = 360;
        rs.shadows = false;
        rs.antialiasing = false;
    }
    if (cmd.width) rs.width = *cmd.width;
    if (cmd.height) rs.height = *cmd.height;
    if (cmd.fps) rs.fps = *cmd.fps;
    if (cmd.shadows) rs.shadows = *cmd.shadows;
    if (cmd.antialiasing) rs.antialiasing = *cmd.antialiasing;
    if (cmd.overlay) rs.overlay = *cmd.overlay;
    if (cmd.axes) rs.axes = *cmd.axes;
    if (cmd.vectors) rs.vectors = *cmd.vectors;
    if (rs.width < 16 || rs.height < 16)
        throw SceneError("--width/--height",
                         std::to_string(rs.width) + "x" + std::to_string(rs.height),
                         "expected at least 16x16 pixels");
    if (rs.fps < 1) throw SceneError("--fps", std::to_string(rs.fps), "expected at least 1");
}

void check_frame_index(const RenderCommand& cmd, const Timeline& tl) {
    if (cmd.frame && (*cmd.frame < 0 || *cmd.frame >= tl.frames))
        throw SceneError("--frame", std::to_string(*cmd.frame),
                         "expected a frame index in [0, " + std::to_string(tl.frames - 1) + "]");
}

std::string output_name(const RenderCommand& cmd, const Scene& scene, const std::string& suffix) {
    if (!cmd.output.empty()) return cmd.output;
    const std::string stem = std::filesystem::path(scene.source).stem().string();
    return (stem.empty() ? "tumble" : stem) + suffix + ".mp4";
}

std::string output_problem(const RenderCommand& cmd, const std::string& output) {
    if (cmd.frame && !output.ends_with(".png"))
        return "--frame renders one still: the output must end in .png, got " + output;
    return "";
}

std::unique_ptr<render::FrameSink> open_render_sink(const RenderCommand& cmd, const Scene& scene,
                                                    const std::string& output) {
    const auto parent = std::filesystem::path(output).parent_path();
    if (!parent.empty() && output.find('%') == std::string::npos)
        std::filesystem::create_directories(parent);
    render::SinkOptions options;
    options.width = scene.render.width;
    options.height = scene.render.height;
    options.fps = scene.render.fps;
    options.crf = cmd.crf;
    options.preset = video_preset(cmd);
    return render::open_sink(output, options);
}

std::string video_preset(const RenderCommand& cmd) {
    if (cmd.preset) return *cmd.preset;
    return cmd.preview ? "ultrafast" : "veryfast";
}

render::RenderOptions render_options(const RenderSettings& rs) {
    render::RenderOptions o;
    o.width = rs.width;
    o.height = rs.height;
    o.samples = rs.antialiasing ? 4 : 1;
    o.shadows = rs.shadows;
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

RunResult render_frames(const Scene& scene, const Timeline& tl, Simulation& sim,
                        render::FrameSink& sink, std::int64_t first, std::int64_t last,
                        bool quiet) {
    tune_allocator_for_rendering();
    RunResult out;
    FrameSource source(scene, tl, sim, first, last);
    Progress progress("rendering", last - first + 1, quiet);
    PipelineStages stages;
    stages.produce = [&](render::SceneView& view) {
        if (InterruptGuard::requested()) {
            out.interrupted = true;
            return false;
        }
        return source.next(view);
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
