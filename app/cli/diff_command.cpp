// `tumble diff a.png b.png`: the golden-image comparison, for scripts. Exit 0 when the images
// match within the budget, 1 when they differ (or the diff image cannot be written), 2 when an
// image cannot be read.
#include "app/cli/failure.h"
#include "app/cli/subcommand.h"
#include "io/bad_input.h"
#include "render/image_compare.h"
#include "render/png_io.h"

#include <cstdio>
#include <memory>

namespace tumble::app {
namespace {

struct DiffCommand {
    std::string a, b;
    std::string output; // diff image, optional
    render::CompareOptions options;
};

render::Image read_input(const std::string& path) {
    try {
        return render::read_png(path);
    } catch (const std::exception& e) {
        throw io::BadInput(e.what());
    }
}

int run_diff(const DiffCommand& cmd) {
    const render::Image a = read_input(cmd.a), b = read_input(cmd.b);
    const render::CompareResult r = render::compare_images(a, b, cmd.options);
    std::printf("%s\n", r.summary.c_str());
    if (!cmd.output.empty() && r.same_size) {
        render::write_png(cmd.output, r.diff);
        std::printf("diff image: %s\n", cmd.output.c_str());
    }
    return r.matches ? kOk : kRunFailed;
}

} // namespace

Subcommand add_diff_command(CLI::App& app) {
    auto cmd = std::make_shared<DiffCommand>();
    CLI::App* d = app.add_subcommand(
        "diff", "compare two PNG images by decoded pixels (exit 0 match, 1 differ)");
    // Exact by default; a suite's image checks set their budget (docs/regression-testing.md).
    d->option_defaults()->always_capture_default();
    d->add_option("a", cmd->a, "first image")->required();
    d->add_option("b", cmd->b, "second image")->required();
    d->add_option("-o,--output", cmd->output,
                  "write a diff image (red: different, yellow: anti-aliasing)");
    d->add_option("--tolerance", cmd->options.tolerance, "per-channel difference ignored (0..255)")
        ->check(CLI::Range(0, 255));
    d->add_option("--threshold", cmd->options.perceptual_threshold,
                  "YIQ perceptual threshold (0..1)")
        ->check(CLI::Range(0.0, 1.0));
    d->add_option("--max-different", cmd->options.max_different, "pixels allowed to differ");
    d->add_option("--max-cluster", cmd->options.max_cluster,
                  "largest cluster of touching differing pixels allowed (default: any)");
    d->add_flag_callback(
        "--no-aa", [cmd] { cmd->options.detect_antialiasing = false; },
        "count anti-aliased pixels as different (default: anti-aliasing is forgiven)");
    return {[d] { return d->parsed(); }, [cmd] { return run_diff(*cmd); }};
}

} // namespace tumble::app
