#pragma once
// A subcommand of `tumble`. Each lives in its own <name>_command.cpp, registers its options on the
// parser and says what to run once the command line is parsed; main.cpp only collects them.
// A command returns its exit code or throws; run_guarded() (app/cli/failure.h) maps what it
// throws.
#include <CLI/CLI.hpp>

#include <functional>

namespace tumble::app {

struct Subcommand {
    std::function<bool()> chosen; // was it given on the command line?
    std::function<int()> run;
};

Subcommand add_render_command(CLI::App& app); // render (and render --compare)
Subcommand add_simulate_command(CLI::App& app);
Subcommand add_explain_command(CLI::App& app);
Subcommand add_scenes_command(CLI::App& app);
Subcommand add_test_command(CLI::App& app);
Subcommand add_schema_command(CLI::App& app);
Subcommand add_diff_command(CLI::App& app);
Subcommand add_study_command(CLI::App& app);
Subcommand add_plot_command(CLI::App& app);
Subcommand add_join_command(CLI::App& app); // docs/cluster.md: join, shards, sweep
Subcommand add_shards_command(CLI::App& app);
Subcommand add_sweep_command(CLI::App& app);
Subcommand add_version_flag(CLI::App& app); // tumble --version

} // namespace tumble::app
