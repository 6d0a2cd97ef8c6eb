// `tumble test SUITE`: runs a regression suite (docs/regression-testing.md) and says, check by
// check, what passed and what did not. Exit 0 every selected check passed, 1 some failed (or a
// scene's run failed), 2 a bad suite, option or output, or a filter that selects nothing.
//   --jobs N      scenes run on N threads; the results are the same for any N
//   --filter PAT  only the checks whose name, or whose scene's name, matches (shell patterns)
//   --update      write the goldens of the failing checks (missing ones included) from this run
//                 and list them; --force replaces images drawn by another GL renderer
//   --junit FILE  JUnit XML for CI servers; --report DIR an HTML report for people
#include "app/cli/failure.h"
#include "app/cli/subcommand.h"
#include "app/regression/golden_update.h"
#include "app/regression/html_report.h"
#include "app/regression/junit_report.h"
#include "app/regression/suite.h"
#include "app/regression/suite_runner.h"
#include "io/bad_input.h"
#include "io/interrupt.h"
#include "io/output_target.h"

#include <cstdio>
#include <memory>

namespace tumble::app {
namespace {

struct TestCommand {
    std::string suite;
    int jobs = 1;
    std::vector<std::string> filters;
    bool update = false, force = false;
    std::string junit, report;
};

// Outputs are checked before anything runs: a bad name is bad input, not a wasted run.
void check_outputs(const TestCommand& cmd) {
    if (cmd.force && !cmd.update) throw io::BadInput("--force goes with --update");
    if (!cmd.junit.empty()) io::resolve_output(cmd.junit);
    std::error_code ec;
    if (!cmd.report.empty() && std::filesystem::exists(cmd.report, ec) &&
        !std::filesystem::is_directory(cmd.report, ec))
        throw io::BadInput("--report " + cmd.report + ": not a folder");
}

void print_results(const SuiteRun& run) {
    for (const CheckResult& r : run.results) {
        std::printf("%-6s %s: %s\n", r.passed ? "ok" : "FAIL", r.name().c_str(), r.summary.c_str());
        for (const std::string& d : r.details) std::printf("         %s\n", d.c_str());
        if (!r.update.empty() && !r.golden_missing)
            std::printf("         update: %s\n", r.update.c_str());
    }
}

int report_update(const UpdateResult& u) {
    for (const std::string& line : u.lines) std::printf("%s\n", line.c_str());
    std::printf("%d golden(s) written, %d unchanged (their checks pass)\n", u.written, u.unchanged);
    return u.impossible == 0 ? kOk : kRunFailed;
}

int run_test(const TestCommand& cmd) {
    check_outputs(cmd);
    // Ctrl-C: loading (auto's pilots) stops; the scenes running stop at their next frame, then
    // nothing more is written.
    io::InterruptGuard guard;
    const Suite suite = load_suite(cmd.suite);
    const Selection selection = select_checks(suite, cmd.filters);
    std::printf("tumble test %s: %zu of %zu checks, %d job(s)\n", cmd.suite.c_str(),
                selection.count, suite.check_count(), cmd.jobs);
    std::fflush(stdout);
    const SuiteRun run = run_suite(suite, selection, cmd.jobs);
    if (run.interrupted) {
        std::fprintf(stderr,
                     "tumble: test interrupted after %zu of %zu checks; no report, "
                     "JUnit file or golden written\n",
                     run.results.size(), selection.count);
        return interrupted_exit_code(io::InterruptGuard::signal_number());
    }
    if (run.gl.known()) std::printf("GL: %s\n", run.gl.describe().c_str());
    print_results(run);
    if (!cmd.report.empty()) write_html_report(cmd.report, suite, run);
    if (!cmd.junit.empty()) write_junit(cmd.junit, suite, run, cmd.report);
    const std::size_t failed = run.failed();
    std::printf("%zu checks: %zu passed, %zu failed\n", run.results.size(),
                run.results.size() - failed, failed);
    if (!cmd.report.empty())
        std::printf("report: %s\n", (std::filesystem::path(cmd.report) / "index.html").c_str());
    std::fprintf(stderr, "tumble: test: %.1f s with %d job(s)\n", run.seconds, cmd.jobs);
    if (cmd.update) return report_update(update_goldens(suite, run, cmd.force));
    if (failed > 0 && cmd.report.empty())
        std::printf("to see the images and plots: add --report DIR\n");
    return failed == 0 ? kOk : kRunFailed;
}

} // namespace

Subcommand add_test_command(CLI::App& app) {
    auto cmd = std::make_shared<TestCommand>();
    CLI::App* t = app.add_subcommand(
        "test", "run a regression suite of image and state checks (exit 0 pass, 1 fail)");
    t->add_option("suite", cmd->suite, "suite JSON (docs/regression-testing.md)")->required();
    t->add_option("-j,--jobs", cmd->jobs, "scenes run in parallel (default 1); same results")
        ->check(CLI::Range(1, 256));
    t->add_option("--filter", cmd->filters,
                  "only checks whose name or scene name matches this shell pattern (repeatable)")
        ->allow_extra_args(false); // one pattern per --filter: `--filter a suite.json` works
    t->add_flag("--update", cmd->update,
                "write the goldens of failing checks from this run and list them");
    t->add_flag("--force", cmd->force,
                "with --update: replace images drawn by another GL renderer too");
    t->add_option("--junit", cmd->junit, "write JUnit XML (for CI) to this file");
    t->add_option("--report", cmd->report, "write an HTML report (index.html, images/) here");
    return {[t] { return t->parsed(); }, [cmd] { return run_test(*cmd); }};
}

} // namespace tumble::app
