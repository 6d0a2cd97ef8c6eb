#include "app/regression/image_judge.h"

#include "render/png_io.h"

#include <algorithm>
#include <cstring>

namespace tumble::app {

render::Image masked(const render::Image& actual, const render::Image& expected,
                     const std::vector<Mask>& masks) {
    render::Image out = actual;
    for (const Mask& m : masks) {
        const int x0 = std::clamp(m.x, 0, out.width), x1 = std::clamp(m.x + m.width, 0, out.width);
        const int y0 = std::clamp(m.y, 0, out.height);
        const int y1 = std::clamp(m.y + m.height, 0, out.height);
        for (int y = y0; y < y1 && x1 > x0; ++y)
            std::memcpy(out.row(y) + 3 * x0, expected.row(y) + 3 * x0, std::size_t(3 * (x1 - x0)));
    }
    return out;
}

void judge_image(const ImageCheck& check, const GlIdentity& here, const GoldenRenderers& record,
                 CheckResult& r) {
    ImageOutcome& out = r.image_outcome;
    std::error_code ec;
    if (!std::filesystem::exists(check.golden, ec)) {
        r.golden_missing = true;
        r.summary = "no golden image " + check.golden.string();
        return;
    }
    try {
        out.expected = render::read_png(check.golden);
    } catch (const render::PngError& e) {
        r.summary = std::string("cannot read the golden image: ") + e.what();
        return;
    }
    out.golden_gl = record.of(check.golden.filename().string());
    r.golden_from_other_gl = out.golden_gl.known() && here.known() && !(out.golden_gl == here);
    const bool same_size =
        out.expected.width == out.actual.width && out.expected.height == out.actual.height;
    const render::Image compared =
        same_size ? masked(out.actual, out.expected, check.masks) : out.actual;
    out.compare = render::compare_images(compared, out.expected, check.compare);
    r.passed = out.compare.matches;
    r.summary = out.compare.summary + (same_size ? "" : " (drawing vs golden)");
    if (!check.masks.empty())
        r.details.push_back(std::to_string(check.masks.size()) + " masked rectangle(s) ignored");
    if (r.golden_from_other_gl)
        r.details.push_back("the golden was drawn by " + out.golden_gl.describe() +
                            "; this machine has " + here.describe() +
                            (r.passed ? "" : ": a difference may come from the renderer"));
}

} // namespace tumble::app
