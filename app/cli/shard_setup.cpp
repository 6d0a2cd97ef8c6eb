#include "app/cli/shard_setup.h"

#include "app/cluster/checkpoint_store.h"
#include "app/cluster/shard_tag.h"
#include "io/bad_input.h"

#include <cctype>
#include <cstdio>
#include <filesystem>

namespace tumble::app {

namespace {

std::string lowercase(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

bool is_mp4(const std::string& output) {
    return lowercase(output).ends_with(".mp4");
}

// A shard is an MP4 (joined later), PNG frames (a folder or a pattern) or null (timing).
void check_shard_output(const std::string& output) {
    const std::string o = lowercase(output);
    const bool frames = o.ends_with('/') || o.find('%') != std::string::npos ||
                        std::filesystem::is_directory(output);
    if (is_mp4(output) || frames || o == "null") return;
    throw io::BadInput("--frames renders a shard: to an .mp4 video (then `tumble join`) or to PNG "
                       "frames (frames/ or frames/%06d.png, numbered as in the whole run), got " +
                       output);
}

} // namespace

FrameRange render_range(RenderCommand& cmd, const Scene& scene, const Timeline& tl) {
    if (cmd.frame) return {*cmd.frame, *cmd.frame + 1};
    if (!cmd.frames) return {0, tl.frames};
    const bool named = !cmd.output.empty(); // else an MP4 named after the scene and range
    if (named) check_shard_output(cmd.output);
    const int keys = !named || is_mp4(cmd.output) ? key_interval(tl.fps) : 1;
    const FrameRange r = parse_frame_range("--frames", *cmd.frames, tl.frames, keys);
    if (!named) {
        char name[64];
        std::snprintf(name, sizeof name, "_%06lld-%06lld.mp4", static_cast<long long>(r.first),
                      static_cast<long long>(r.end));
        cmd.output = scene_name(scene) + name;
    }
    return r;
}

RunOutput run_output(const RenderCommand& cmd, const Scene& scene, const Timeline& tl,
                     FrameRange range, const std::string& output) {
    RunOutput run;
    if (cmd.frames) {
        run.first_frame = range.first;
        run.end_frame = range.end;
    }
    if (is_mp4(output) && !cmd.frame)
        run.comment = format_tag(shard_tag_for(scene, tl, range, cmd.crf, video_preset(cmd)));
    return run;
}

std::optional<ResumePoint> resume_point(const RenderCommand& cmd, const Scene& scene,
                                        const Timeline& tl, const Simulation& sim,
                                        FrameRange range) {
    if (cmd.from_checkpoints.empty()) return std::nullopt;
    std::optional<ResumePoint> resume =
        nearest_checkpoint(cmd.from_checkpoints, range.first, scene, tl, sim);
    if (!cmd.common.quiet) {
        if (resume)
            std::fprintf(stderr, "tumble: note: continuing from %s (frame %lld)\n",
                         checkpoint_path(cmd.from_checkpoints, resume->frame).c_str(),
                         static_cast<long long>(resume->frame));
        else
            std::fprintf(stderr,
                         "tumble: note: no checkpoint at or before frame %lld in %s: simulating "
                         "from t = 0\n",
                         static_cast<long long>(range.first), cmd.from_checkpoints.c_str());
    }
    return resume;
}

} // namespace tumble::app
