#pragma once
// Command-line mistakes, said the way every other error is: "tumble: error: ...", a guess at what
// was meant ("did you mean --fps?"), and where to read more. Exit code 2 (bad input).
#include <CLI/CLI.hpp>

namespace tumble::app {

// Prints the error of a failed parse of `app` and returns kBadInput.
int report_usage_error(const CLI::App& app, const CLI::ParseError& error);

// `tumble` with no subcommand: the usage on stderr, and kBadInput.
int report_missing_command(const CLI::App& app);

} // namespace tumble::app
