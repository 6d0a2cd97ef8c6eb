// render_bench: how fast frames go through the pipeline (app/run/pipeline.h), per stage and end
// to end, for the fixed cases of render_cases.h. A benchmark, not a test: it asserts nothing, it
// measures. scripts/bench-render.sh runs it and keeps the CSV; this file only reads the options.
//   render_bench [CASE...] [--repeats N] [--csv FILE] [--machine LABEL] [--quick]
// Exit codes as tumble's (app/cli/failure.h): 2 for bad options or an unknown case, 1 for a run
// that failed, 128 + signal on Ctrl-C or SIGTERM.
#include "bench/render/render_table.h"

#include "io/bad_input.h"
#include "io/interrupt.h"

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

namespace {

struct Options {
    std::vector<std::string> cases; // empty: all
    int repeats = 3;
    std::string csv;     // append the table here
    std::string machine; // label for the CSV (default: the host name)
    bool quick = false;  // fewer frames per case
};

// A folder of this process's outputs under the temporary directory, removed when done.
struct ScratchDir {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("tumble-bench-" + std::to_string(::getpid()));
    ~ScratchDir() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
};

int run(const Options& o) {
    using namespace tumble::bench;
    const std::vector<const RenderCase*> cases = select_cases(o.cases);
    std::vector<RenderRow> rows;
    {
        const ScratchDir scratch;
        for (const RenderCase* c : cases)
            rows.push_back(measure(*c, o.repeats, o.quick, scratch.path));
    }
    const double load = load_average();
    print_table(rows, o.repeats, load);
    if (!o.csv.empty()) {
        append_csv(o.csv, o.machine.empty() ? host_name() : o.machine, rows, load);
        std::printf("appended to %s\n", o.csv.c_str());
    }
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    Options o;
    CLI::App app("frame rates per pipeline stage and end to end, against a null sink",
                 "render_bench");
    app.add_option("cases", o.cases, "cases to run (default: all; see bench/README.md)");
    app.add_option("--repeats", o.repeats, "runs per case; the table shows medians (default 3)")
        ->check(CLI::PositiveNumber);
    app.add_option("--csv", o.csv, "append the results to this CSV file");
    app.add_option("--machine", o.machine, "machine label in the CSV (default: host name)");
    app.add_flag("--quick", o.quick, "fewer frames per case");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    }
    const tumble::io::InterruptGuard interrupts;
    try {
        return run(o);
    } catch (const tumble::io::Interrupted& e) {
        std::fprintf(stderr, "render_bench: %s\n", e.what());
        return 128 + e.signal_number;
    } catch (const tumble::io::BadInput& e) {
        std::fprintf(stderr, "render_bench: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "render_bench: %s\n", e.what());
        return 1;
    }
}
