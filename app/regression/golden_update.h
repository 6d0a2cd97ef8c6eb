#pragma once
// `tumble test --update`: writes the goldens of the checks that failed (a missing golden
// included) from what this run drew and sampled, and leaves the passing ones untouched, so that
// a renderer's last-bit noise within tolerance never churns the committed files. Refuses, before
// writing anything, to replace images drawn by another GL renderer unless `force`.
#include "app/regression/check_result.h"

#include <string>
#include <vector>

namespace tumble::app {

struct UpdateResult {
    std::vector<std::string> lines; // one per golden written or refused, for people
    int written = 0;
    int unchanged = 0;  // checks that passed
    int impossible = 0; // checks whose run failed: nothing to write
};

// Throws io::BadInput (nothing written) when a golden to replace came from another renderer and
// not `force`; a write that fails throws what io/ and render/ throw (a failed run).
UpdateResult update_goldens(const Suite& suite, const SuiteRun& run, bool force);

} // namespace tumble::app
