// `tumble diff a.png b.png`: the golden-image comparison, for scripts. Exit 0 when the images
// match within the budget, 1 when they differ, 2 when a file cannot be read.
#include "app/commands.h"
#include "app/scene_options.h"
#include "render/image_compare.h"
#include "render/png_io.h"

#include <cstdio>

namespace tumble::app {

int run_diff(const DiffCommand& cmd) {
    render::Image a, b;
    try {
        a = render::read_png(cmd.a);
        b = render::read_png(cmd.b);
    } catch (const std::exception& e) {
        return report_error(e.what(), kBadInput);
    }
    const render::CompareResult r = render::compare_images(a, b, cmd.options);
    std::printf("%s\n", r.summary.c_str());
    if (!cmd.output.empty() && r.same_size) {
        try {
            render::write_png(cmd.output, r.diff);
            std::printf("diff image: %s\n", cmd.output.c_str());
        } catch (const std::exception& e) {
            return report_error(e.what(), kBadInput);
        }
    }
    return r.matches ? kOk : kRunFailed;
}

} // namespace tumble::app
