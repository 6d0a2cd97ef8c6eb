#pragma once
// The whole `tumble` command line: collects the subcommands, parses argv and runs the one given.
// In the cli library, so that CLI11's templates are instantiated once, in its unity batches, and
// the executable's main.cpp compiles in a moment (docs/engineering.md).

namespace tumble::app {

// Returns the process exit code (app/cli/failure.h maps every failure to one).
int tumble_main(int argc, char** argv);

} // namespace tumble::app
