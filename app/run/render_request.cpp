#include "app/run/render_request.h"

#include "app/run/key_interval.h"
#include "app/run/stale_temporaries.h"
#include "app/scene/scene_error.h"
#include "app/view/poinsot.h"
#include "io/bad_input.h"
#include "render/open_sink.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace tumble::app {

namespace {

// --chart, --chart-body, --chart-window, --trails, --trail-axis, --poinsot, --overlay-body.
void apply_teaching_overrides(const RenderRequest& cmd, Scene& scene) {
    RenderSettings& rs = scene.render;
    if (cmd.chart) {
        rs.chart.clear();
        for (const std::string& name : *cmd.chart) {
            const auto q = parse_quantity(name);
            if (!q) throw SceneError("--chart", name, "expected one of " + quantity_names());
            rs.chart.push_back(*q);
        }
    }
    if (cmd.chart_body) rs.chart_body = {*cmd.chart_body, "--chart-body"};
    if (cmd.chart_window) rs.chart_window = *cmd.chart_window;
    if (cmd.trails) rs.trails = *cmd.trails;
    if (cmd.trail_seconds) rs.trail_seconds = *cmd.trail_seconds;
    if (cmd.trail_axis) {
        const std::string& a = *cmd.trail_axis;
        if (a != "x" && a != "y" && a != "z")
            throw SceneError("--trail-axis", a, "expected x, y or z");
        rs.trail_axis = a[0] - 'x';
        rs.trails = true;
    }
    if (cmd.poinsot) rs.poinsot = {*cmd.poinsot, "--poinsot"};
    if (cmd.poinsot && !cmd.camera) rs.camera.mode = CameraRig::Mode::Poinsot; // frame it
    if (cmd.overlay_body) {
        rs.overlay_body = {*cmd.overlay_body, "--overlay-body"};
        rs.overlay = true;
    }
    resolve_render_bodies(scene);
    if (const std::string w = poinsot_warning(scene); !w.empty() && !cmd.quiet)
        std::fprintf(stderr, "tumble: warning: %s\n", w.c_str());
}

} // namespace

void apply_render_overrides(const RenderRequest& cmd, Scene& scene) {
    RenderSettings& rs = scene.render;
    if (cmd.preview) { // a quick look: small, no shadows, no anti-aliasing, no extras
        rs.width = 640;
        rs.height = 360;
        rs.shadows = false;
        rs.antialiasing = false;
        rs.ambient_occlusion = false;
        rs.reflections = false;
    }
    if (cmd.width) rs.width = *cmd.width;
    if (cmd.height) rs.height = *cmd.height;
    if (cmd.fps) rs.fps = *cmd.fps;
    if (cmd.shadows) rs.shadows = *cmd.shadows;
    if (cmd.soft_shadows) rs.soft_shadows = *cmd.soft_shadows;
    if (cmd.ambient_occlusion) rs.ambient_occlusion = *cmd.ambient_occlusion;
    if (cmd.reflections) rs.reflections = *cmd.reflections;
    if (cmd.antialiasing) rs.antialiasing = *cmd.antialiasing;
    if (cmd.overlay) rs.overlay = *cmd.overlay;
    if (cmd.axes) rs.axes = *cmd.axes;
    if (cmd.vectors) rs.vectors = *cmd.vectors;
    if (cmd.camera) read_camera_option(*cmd.camera, "--camera", rs.camera);
    apply_teaching_overrides(cmd, scene);
    if (rs.width < rs.kMinSide || rs.height < rs.kMinSide || rs.width > rs.kMaxWidth ||
        rs.height > rs.kMaxHeight)
        throw SceneError("--width/--height",
                         std::to_string(rs.width) + "x" + std::to_string(rs.height),
                         "expected 16x16 to 7680x4320 pixels (8K UHD, the largest frame Tumble "
                         "draws)");
    if (rs.fps < 1) throw SceneError("--fps", std::to_string(rs.fps), "expected at least 1");
}

std::string resolve_time(RenderRequest& cmd, const Timeline& tl) {
    if (!cmd.time) return "";
    const double t = *cmd.time;
    const double last = tl.frame_time(tl.frames - 1);
    char text[160];
    std::snprintf(text, sizeof text, "%.9g", t);
    if (!std::isfinite(t) || t < 0.0 || std::llround(t * tl.fps) > tl.frames - 1) {
        char range[64];
        std::snprintf(range, sizeof range, "expected a time in [0, %.9g] s", last);
        throw SceneError("--time", text, range);
    }
    cmd.frame = std::llround(t * tl.fps);
    if (std::abs(tl.frame_time(*cmd.frame) - t) <= 1e-9 * std::max(1.0, t)) return "";
    char note[200];
    std::snprintf(note, sizeof note,
                  "t = %.9g s is between frames at %d fps: frame %lld, t = %.9g s", t, tl.fps,
                  static_cast<long long>(*cmd.frame), tl.frame_time(*cmd.frame));
    return note;
}

void check_frame_index(const RenderRequest& cmd, const Timeline& tl) {
    if (cmd.frame && (*cmd.frame < 0 || *cmd.frame >= tl.frames))
        throw SceneError("--frame", std::to_string(*cmd.frame),
                         "expected a frame index in [0, " + std::to_string(tl.frames - 1) + "]");
}

std::string output_name(const RenderRequest& cmd, const Scene& scene, const std::string& suffix) {
    std::string output = cmd.output;
    if (output.empty() && cmd.frame) { // a still: "default_000120.png"
        char number[32];
        std::snprintf(number, sizeof number, "_%06lld", static_cast<long long>(*cmd.frame));
        output = scene_name(scene) + suffix + number + ".png";
    } else if (output.empty()) {
        output = scene_name(scene) + suffix + ".mp4";
    }
    if (cmd.frame && !output.ends_with(".png"))
        throw io::BadInput("--frame renders one still: the output must end in .png, got " + output);
    return output;
}

std::unique_ptr<render::FrameSink> open_render_sink(const RenderRequest& cmd, const Scene& scene,
                                                    const std::string& output, const RunOutput& run,
                                                    bool quiet) {
    // The folders above the output. A PNG sequence's own folder ("frames/") is left to the sink,
    // which creates it and removes it again if the run fails before a frame is kept.
    auto parent = std::filesystem::path(output).parent_path();
    if (output.ends_with('/')) parent = parent.parent_path();
    std::error_code ec;
    if (!parent.empty() && output.find('%') == std::string::npos)
        std::filesystem::create_directories(parent, ec);
    if (ec)
        throw io::BadInput("cannot create the folder '" + parent.string() + "' of '" + output +
                           "': " + ec.message());
    render::SinkOptions options;
    options.width = scene.render.width;
    options.height = scene.render.height;
    options.fps = scene.render.fps;
    options.crf = cmd.crf;
    options.overwrite = cmd.overwrite;
    options.preset = video_preset(cmd);
    options.key_interval = key_interval(scene.render.fps);
    options.first_frame = run.first_frame;
    options.end_frame = run.end_frame;
    options.comment = run.comment;
    remove_stale_temporaries_for(output, quiet);
    try {
        return render::open_sink(output, options);
    } catch (const render::SinkError& e) {
        throw io::BadInput(e.what());
    }
}

std::string video_preset(const RenderRequest& cmd) {
    if (cmd.preset) return *cmd.preset;
    return cmd.preview ? "ultrafast" : "medium";
}

} // namespace tumble::app
