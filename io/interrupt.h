#pragma once
// Ctrl-C and SIGTERM: the first one asks the running command to stop at the next frame boundary
// and finish its outputs (so a video plays); a second one exits at once, deleting the temporary
// files of outputs still in progress (io/temporary_files.h), so nothing half-written is left. The
// exit code is then 128 + signal number (130 for SIGINT, 143 for SIGTERM), as shells expect.
namespace tumble::app {

class InterruptGuard {
  public:
    InterruptGuard();  // installs the handlers
    ~InterruptGuard(); // restores the previous ones
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

    static bool requested();    // a signal arrived
    static int signal_number(); // which one (0 if none)
};

} // namespace tumble::app
