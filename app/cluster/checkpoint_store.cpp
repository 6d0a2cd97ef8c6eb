#include "app/cluster/checkpoint_store.h"

#include "app/cluster/build_id.h"
#include "io/atomic_file.h"
#include "io/bad_input.h"
#include "physics/integrator.h"
#include "physics/state_fields.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <stdexcept>

namespace tumble::app {

namespace fs = std::filesystem;

fs::path checkpoint_path(const fs::path& dir, std::int64_t frame) {
    char name[48];
    std::snprintf(name, sizeof name, "frame_%06lld.tck", static_cast<long long>(frame));
    return dir / name;
}

CheckpointHeader run_header(const Scene& scene, const Timeline& tl, const Simulation& sim,
                            std::int64_t frame) {
    CheckpointHeader h;
    h.scene_hash = scene.content_hash;
    h.build = build_id();
    h.integrator = std::string(physics::integrator_info(sim.model.integrator).name);
    h.h = tl.h;
    h.fps = tl.fps;
    h.steps_per_frame = tl.steps_per_frame;
    h.frame = frame;
    h.bodies = sim.model.body_count();
    return h;
}

void save_checkpoint(const fs::path& dir, const Scene& scene, const Timeline& tl,
                     const Simulation& sim, std::int64_t frame) {
    if (sim.state.step != frame * tl.steps_per_frame)
        throw std::logic_error("save_checkpoint: the state is not at frame " +
                               std::to_string(frame));
    write_checkpoint(checkpoint_path(dir, frame), run_header(scene, tl, sim, frame), sim.state);
}

std::vector<std::int64_t> checkpoint_frames(const fs::path& dir) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        throw io::BadInput("--from-checkpoints " + dir.string() + ": " +
                           (fs::exists(dir, ec) ? "not a directory"
                                                : "no such directory (make one with `tumble "
                                                  "simulate SCENE --checkpoint-every K "
                                                  "--checkpoints DIR`)"));
    std::vector<std::int64_t> frames;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (!name.starts_with("frame_") || !name.ends_with(".tck")) continue;
        const std::string digits = name.substr(6, name.size() - 10);
        std::int64_t k = 0;
        const auto [at, err] = std::from_chars(digits.data(), digits.data() + digits.size(), k);
        if (err == std::errc() && at == digits.data() + digits.size() && !digits.empty() && k >= 0)
            frames.push_back(k);
    }
    std::sort(frames.begin(), frames.end());
    return frames;
}

std::optional<ResumePoint> nearest_checkpoint(const fs::path& dir, std::int64_t frame,
                                              const Scene& scene, const Timeline& tl,
                                              const Simulation& sim) {
    const std::vector<std::int64_t> frames = checkpoint_frames(dir);
    const auto after = std::upper_bound(frames.begin(), frames.end(), frame);
    if (after == frames.begin()) return std::nullopt;
    const std::int64_t k = *(after - 1);
    const fs::path file = checkpoint_path(dir, k);
    Checkpoint c = read_checkpoint(file);
    const auto refuse = [&](const std::string& why) {
        return CheckpointError(file.string() + ": cannot continue this run from it: " + why);
    };
    if (const std::string why = header_mismatch(c.header, run_header(scene, tl, sim, k));
        !why.empty())
        throw refuse(why);
    if (c.header.frame != k || c.state.step != k * tl.steps_per_frame)
        throw refuse("its name says frame " + std::to_string(k) + ", its contents frame " +
                     std::to_string(c.header.frame) + " at step " + std::to_string(c.state.step));
    if (const std::string why = physics::state_mismatch(sim.model, c.state); !why.empty())
        throw refuse("its state does not fit the scene: " + why);
    return ResumePoint{k, std::move(c.state)};
}

} // namespace tumble::app
