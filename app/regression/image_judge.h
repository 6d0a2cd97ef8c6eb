#pragma once
// An image check's judgement: the drawing against its golden PNG with the check's comparison
// (render/image_compare.h: exact first, then anti-aliasing-aware within a budget), the masked
// rectangles ignored, and the golden's renderer held against this machine's.
#include "app/regression/check_result.h"
#include "app/regression/golden_renderers.h"

namespace tumble::app {

// Fills result.image_outcome (expected, compare, golden_gl), passed, summary and details from
// result.image_outcome.actual. A golden that is missing or unreadable fails the check.
void judge_image(const ImageCheck& check, const GlIdentity& this_machine,
                 const GoldenRenderers& record, CheckResult& result);

// `actual` with the pixels under `masks` taken from `expected` (same size): what is compared.
render::Image masked(const render::Image& actual, const render::Image& expected,
                     const std::vector<Mask>& masks);

} // namespace tumble::app
