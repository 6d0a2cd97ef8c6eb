#include "bench/render/render_measure.h"

#include "app/run/auto_camera.h"
#include "app/run/prepare_run.h"
#include "app/run/render_frames.h"
#include "app/run/render_request.h"
#include "render/open_sink.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <ctime>

namespace tumble::bench {
namespace {

// The case's picture switches as `tumble render` takes them (app/run/render_request.h).
app::RenderRequest request_of(const RenderCase& c) {
    app::RenderRequest r;
    r.preview = c.preview;
    r.width = c.width;
    r.height = c.height;
    r.shadows = c.shadows;
    r.antialiasing = c.antialiasing;
    r.soft_shadows = c.soft_shadows;
    r.ambient_occlusion = c.ambient_occlusion;
    r.reflections = c.reflections;
    if (c.teaching) {
        r.chart = std::vector<std::string>{"energy", "w_body"};
        r.chart_body = "book";
        r.trails = true;
        r.poinsot = "book";
    }
    return r;
}

// One run of a case into `output` (a file, a folder, or "null"), prepared as every command
// prepares its runs (app/run/prepare_run.h) and encoded as `tumble render` would encode it.
app::PipelineStats run_once(const RenderCase& c, int frames, const std::string& output) {
    app::Scene scene = load_case_scene(c);
    const app::RenderRequest request = request_of(c);
    app::apply_render_overrides(request, scene);
    scene.duration = double(frames) / scene.render.fps;
    app::PreparedRun run = app::prepare_run(std::move(scene));
    app::frame_automatically(run.scene, run.timeline); // camera.auto: a pre-pass over the run
    const app::Timeline& tl = run.timeline;
    render::SinkOptions so;
    so.width = run.scene.render.width;
    so.height = run.scene.render.height;
    so.fps = run.scene.render.fps;
    so.preset = app::video_preset(request);
    auto sink = render::open_sink(output, so);
    const app::RunResult r =
        app::render_frames(run.scene, tl, run.sim, *sink, 0, tl.frames - 1, true);
    // Finishing is part of the run: the encoder's last frames, and for a GIF both of its
    // palette passes over the spooled frames.
    app::PipelineStats stats = r.stats;
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    sink->finish();
    stats.wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    stats.cpu += double(std::clock() - c0) / CLOCKS_PER_SEC;
    return stats;
}

double per_frame_ms(const app::PipelineStats& s) {
    return 1e3 * s.cpu / double(std::max<std::int64_t>(1, s.frames));
}

} // namespace

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

RenderRow measure(const RenderCase& c, int repeats, bool quick,
                  const std::filesystem::path& scratch) {
    const int frames = quick ? c.quick_frames : c.frames;
    std::vector<double> physics, render, output, e2e, null_render, null_e2e, cpu, null_cpu;
    for (int i = 0; i < repeats; ++i) {
        std::filesystem::remove_all(scratch);
        std::filesystem::create_directories(scratch);
        const std::string out = std::string(c.sink) == "png"
                                    ? (scratch / "frames/").string()
                                    : (scratch / (std::string("bench.") + c.sink)).string();
        const app::PipelineStats real = run_once(c, frames, out);
        const app::PipelineStats null = run_once(c, frames, "null");
        physics.push_back(real.physics.rate());
        render.push_back(real.render.rate());
        output.push_back(real.output.rate());
        e2e.push_back(real.rate());
        null_render.push_back(null.render.rate());
        null_e2e.push_back(null.rate());
        cpu.push_back(per_frame_ms(real));
        null_cpu.push_back(per_frame_ms(null));
        std::fprintf(stderr, "bench: %s run %d/%d: %.1f fps (null sink %.1f fps)\n", c.name, i + 1,
                     repeats, real.rate(), null.rate());
    }
    return {&c,
            frames,
            repeats,
            median(physics),
            median(render),
            median(output),
            median(e2e),
            median(null_render),
            median(null_e2e),
            median(cpu),
            median(null_cpu)};
}

} // namespace tumble::bench
