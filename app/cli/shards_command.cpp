// `tumble shards`: the `tumble render` commands that split a run into N shards on key frames, one
// per line, for GNU parallel, a Slurm array job or any other way of running them on several
// machines (docs/cluster.md). MP4 shards are then joined with `tumble join` (the command is
// printed on stderr); PNG shards write one folder, each frame numbered as in the whole run, and
// need no join.
#include "app/cli/failure.h"
#include "app/cli/scene_options.h"
#include "app/cli/subcommand.h"
#include "app/cluster/frame_range.h"
#include "app/run/timeline.h"
#include "io/bad_input.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tumble::app {
namespace {

struct ShardsCommand {
    SceneOptions common;
    int count = 0;
    std::string output; // the joined video (default <scene>.mp4), or a PNG folder / pattern
    std::optional<int> fps;
    std::string from_checkpoints;
    std::string tumble = "tumble";  // how the printed commands call tumble
    std::vector<std::string> extra; // after --: more render options, added to every command
    bool join = false;              // print the join command instead of the render commands
};

std::string number_text(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", v); // the same double when read back
    return text;
}

// One word for a POSIX shell: as it is when it is plain, else in single quotes.
std::string shell_word(const std::string& s) {
    const bool plain = !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) ||
               std::string_view("_./:=,+%@-").find(c) != std::string_view::npos;
    });
    if (plain) return s;
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

// Options that decide the ranges or the outputs belong to `shards` itself, not after --.
void check_extra(const std::vector<std::string>& extra) {
    static const std::vector<std::string> own = {
        "--frames",     "-o",      "--output", "--from-checkpoints", "--fps", "--duration", "--dt",
        "--integrator", "--frame", "--time",   "--compare"};
    for (const std::string& word : extra)
        for (const std::string& o : own)
            if (word == o || word.starts_with(o + "="))
                throw io::BadInput("shards: " + word + " after --: give " + o +
                                   " to `tumble shards` itself (it decides the ranges and outputs "
                                   "and passes it on)");
}

bool png_output(const std::string& output) {
    return output.ends_with('/') || output.find('%') != std::string::npos;
}

// "out/run.mp4", shard 2 -> "out/run.part002.mp4"; a PNG folder or pattern is shared.
std::string shard_output(const std::string& output, int i) {
    if (png_output(output)) return output;
    const std::string stem =
        output.ends_with(".mp4") ? output.substr(0, output.size() - 4) : output;
    char part[32];
    std::snprintf(part, sizeof part, ".part%03d.mp4", i);
    return stem + part;
}

// The options every render command carries after its range and output: the checkpoints, the
// scene overrides `shards` was given (they decide the frames), then the render options after --.
std::vector<std::string> shared_options(const ShardsCommand& cmd) {
    std::vector<std::string> shared;
    if (!cmd.from_checkpoints.empty()) shared = {"--from-checkpoints", cmd.from_checkpoints};
    const RunRequest& o = cmd.common.run;
    if (o.integrator) shared.insert(shared.end(), {"--integrator", *o.integrator});
    if (o.tolerance) shared.insert(shared.end(), {"--tolerance", *o.tolerance});
    if (o.duration) shared.insert(shared.end(), {"--duration", number_text(*o.duration)});
    if (o.dt) shared.insert(shared.end(), {"--dt", number_text(*o.dt)});
    if (cmd.fps) shared.insert(shared.end(), {"--fps", std::to_string(*cmd.fps)});
    shared.insert(shared.end(), cmd.extra.begin(), cmd.extra.end());
    return shared;
}

std::string command_line(const std::vector<std::string>& words) {
    std::string line;
    for (const std::string& w : words) line += (line.empty() ? "" : " ") + shell_word(w);
    return line;
}

// The shards' ranges: on key frames for a video, anywhere for PNG frames.
std::vector<FrameRange> shard_ranges(const ShardsCommand& cmd, const Scene& scene,
                                     const std::string& output) {
    const int fps = cmd.fps.value_or(scene.render.fps);
    if (fps < 1) throw io::BadInput("--fps " + std::to_string(fps) + ": expected at least 1");
    if (!png_output(output) && !output.ends_with(".mp4"))
        throw io::BadInput("shards -o " + output +
                           ": expected the joined video (NAME.mp4) or PNG frames (frames/ or "
                           "frames/%06d.png)");
    // The frame count only, which the step does not change: no need to plan the run (each
    // shard's `tumble render` plans it, to the same bits).
    const Timeline tl = make_timeline(scene.world.dt, scene.duration, fps);
    return split_frames(tl.frames, png_output(output) ? 1 : key_interval(fps), cmd.count);
}

int run_shards(const ShardsCommand& cmd) {
    check_extra(cmd.extra);
    const Scene scene = load_for_command(cmd.common);
    const std::string output = cmd.output.empty() ? scene_name(scene) + ".mp4" : cmd.output;
    const std::vector<FrameRange> ranges = shard_ranges(cmd, scene, output);
    std::vector<std::string> join = {cmd.tumble, "join"};
    for (int i = 0; i < cmd.count; ++i) join.push_back(shard_output(output, i));
    join.insert(join.end(), {"-o", output});
    if (png_output(output) && (cmd.join || !cmd.common.quiet)) {
        const std::string why = "PNG shards need no join: together they write " + output +
                                ", each frame numbered as in the whole run";
        if (cmd.join) throw io::BadInput("shards --join: " + why);
        std::fprintf(stderr, "tumble: %s\n", why.c_str());
    }
    if (cmd.join) {
        std::printf("%s\n", command_line(join).c_str());
        return kOk;
    }
    const std::vector<std::string> shared = shared_options(cmd);
    for (int i = 0; i < cmd.count; ++i) {
        std::vector<std::string> words = {cmd.tumble,
                                          "render",
                                          cmd.common.scene.empty() ? "default" : cmd.common.scene,
                                          "--frames",
                                          ranges[i].text(),
                                          "-o",
                                          shard_output(output, i)};
        words.insert(words.end(), shared.begin(), shared.end());
        std::printf("%s\n", command_line(words).c_str());
    }
    if (!cmd.common.quiet && !png_output(output))
        std::fprintf(stderr, "tumble: then join them: %s\n", command_line(join).c_str());
    return kOk;
}

} // namespace

Subcommand add_shards_command(CLI::App& app) {
    auto cmd = std::make_shared<ShardsCommand>();
    CLI::App* s = app.add_subcommand(
        "shards", "print the `tumble render --frames A:B` commands of N shards, one per line");
    add_scene_options(s, cmd->common);
    s->add_option("--count", cmd->count, "number of shards")
        ->required()
        ->check(CLI::PositiveNumber);
    s->add_option("-o,--output", cmd->output,
                  "the joined video (default <scene>.mp4; shards NAME.part000.mp4 ...), or PNG "
                  "frames (frames/ or frames/%06d.png) that all shards write");
    s->add_option("--fps", cmd->fps, "frames per second (decides the frame count)");
    s->add_option("--from-checkpoints", cmd->from_checkpoints,
                  "passed on: each shard continues from the nearest checkpoint in DIR");
    s->add_option("--tumble", cmd->tumble, "how the commands call tumble (default: tumble)");
    s->add_flag("--join", cmd->join,
                "print the `tumble join` command of these shards instead (for a dependent job)");
    s->add_option("render_options", cmd->extra,
                  "after --: render options added to every command (e.g. -- --width 640 "
                  "--height 360)");
    return {[s] { return s->parsed(); }, [cmd] { return run_shards(*cmd); }};
}

} // namespace tumble::app
