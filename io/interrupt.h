#pragma once
// Ctrl-C and SIGTERM: the first one asks the running command to stop at the next frame boundary
// and finish its outputs (so a video plays); a second one exits at once, deleting the temporary
// files of outputs still in progress (io/temporary_files.h), so nothing half-written is left. The
// exit code is then 128 + signal number (130 for SIGINT, 143 for SIGTERM), as shells expect.
// A stage with nothing worth keeping yet (camera.auto's pre-pass, auto's pilot runs, a study's
// case) stops at the first signal instead: it throws Interrupted, which run_guarded() (app/cli/
// failure.h) turns into that exit code, and the outputs in progress are deleted as for any failure.
#include <stdexcept>
#include <string>

namespace tumble::io {

struct Interrupted : std::runtime_error {
    Interrupted(const std::string& stage, int signal_number);
    int signal_number;
};

class InterruptGuard {
  public:
    // command: SIGINT and SIGTERM as above, for the `tumble` command line. host: SIGINT only, for
    // a program that embeds Tumble and reports the interruption itself (the Python module raises
    // KeyboardInterrupt once the call has stopped): every signal just sets the flag, with no
    // message and no exit on the second, and SIGTERM keeps the host's own handling; the host reads
    // the flag before the guard goes, which clears it (no later call, on any thread, stops on it).
    enum class Mode { command, host };
    explicit InterruptGuard(Mode mode = Mode::command); // clears the flag, installs the handlers
    ~InterruptGuard();                                  // restores the previous ones
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

    static bool requested();    // a signal arrived
    static int signal_number(); // which one (0 if none)
    // Throws Interrupted naming `stage` ("camera.auto's pre-pass") when a signal arrived.
    static void stop_if_requested(const std::string& stage);

  private:
    Mode mode_;
};

} // namespace tumble::io
