#pragma once
// Every failure of every subcommand, mapped once to an exit code and a message (README, "Exit
// codes"):
//   0  success
//   1  the run failed: a body's state became NaN, a disk filled up, the encoder or the GL
//      context failed, a write or rename failed - anything that is not the user's input
//   2  bad input: a scene (file and place named), an option, an output name or folder
//      (io::BadInput and its subclasses, and command-line parse errors)
//   128 + signal  interrupted by Ctrl-C (130) or SIGTERM (143): outputs finished first when
//      frames were made, else (a stage before the frames: io/interrupt.h)
//      none left behind
// Commands throw; main() runs each through run_guarded(), the only place that catches.
#include <exception>
#include <functional>

namespace tumble::app {

enum ExitCode { kOk = 0, kRunFailed = 1, kBadInput = 2 };

// The exit code of an exception that ended a command: 128 + signal for io::Interrupted, kBadInput
// for io::BadInput, else kRunFailed.
int exit_code_of(const std::exception& e);

// Prints "tumble: error: <what>" (for io::Interrupted, "tumble: <what>") to stderr and returns
// exit_code_of(e).
int report_failure(const std::exception& e);

// Runs a command's body and returns its exit code, or the mapped code of what it threw.
int run_guarded(const std::function<int()>& body) noexcept;

// 128 + signal: the exit code of a run stopped by a signal (Ctrl-C 130, SIGTERM 143).
int interrupted_exit_code(int signal_number);

} // namespace tumble::app
