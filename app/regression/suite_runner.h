#pragma once
// Runs the checks of a suite: the selected ones (--filter), one job per scene on `jobs` threads
// (each job draws and samples its scene in one pass per image size, app/regression/scene_pass.h),
// then judges each check. Results come back in suite order and do not depend on `jobs`: each
// scene's job is the same whichever thread runs it, and llvmpipe draws the same pixels.
#include "app/regression/check_result.h"

#include <string>
#include <vector>

namespace tumble::app {

// The checks of `suite` that `filters` select, as (scene index, check) lists. A filter is a
// shell-style pattern (* ? [...]) matched against check names and scene names; a check is selected
// when any matches, and every check when there is no filter. Throws io::BadInput naming a filter
// that selects nothing, or when the suite has no check at all.
struct Selection {
    std::vector<std::vector<const ImageCheck*>> images; // by scene index
    std::vector<std::vector<const StateCheck*>> states;
    std::size_t count = 0;
};
Selection select_checks(const Suite& suite, const std::vector<std::string>& filters);

// On Ctrl-C or SIGTERM (app/run/interrupt.h, which the caller installs) the scenes running
// finish and no other starts; the run says it was interrupted.
SuiteRun run_suite(const Suite& suite, const Selection& selection, int jobs);

// The command that rewrites one check's golden on purpose, as a user types it.
std::string update_command(const Suite& suite, const std::string& check);

} // namespace tumble::app
