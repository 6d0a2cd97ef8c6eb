#include "io/interrupt.h"

#include "io/temporary_files.h"

#include <atomic>
#include <csignal>
#include <unistd.h>

namespace tumble::io {
namespace {

// Signal handlers may only touch lock-free atomics; this is the one piece of process-wide
// state in Tumble, and it exists because signals are process-wide.
std::atomic<int> g_signal{0};
struct sigaction g_old_int, g_old_term;

void say(const char* text, std::size_t size) {
    const ssize_t ignored = ::write(STDERR_FILENO, text, size);
    (void)ignored;
}

// The second signal: leave now, but not before deleting the temporary files of unfinished
// outputs (unlink and write are async-signal-safe; nothing here allocates or locks).
[[noreturn]] void leave_at_once(int sig) {
    io::remove_registered_temporaries();
    static const char message[] = "\ntumble: interrupted again: stopped at once; outputs in "
                                  "progress were deleted\n";
    say(message, sizeof message - 1);
    _exit(128 + sig);
}

extern "C" void on_signal(int sig) {
    if (g_signal.exchange(sig) != 0) leave_at_once(sig);
    static const char message[] =
        "\ntumble: interrupted: stopping; what is complete is kept (again to "
        "quit at once)\n";
    say(message, sizeof message - 1);
}

// A host's call: the flag only; the host says what happened once the call returns.
extern "C" void on_signal_in_host(int sig) {
    g_signal.store(sig);
}

} // namespace

InterruptGuard::InterruptGuard(Mode mode) : mode_(mode) {
    g_signal = 0;
    struct sigaction sa {};
    sa.sa_handler = mode == Mode::command ? on_signal : on_signal_in_host;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &g_old_int);
    if (mode == Mode::command) sigaction(SIGTERM, &sa, &g_old_term);
}

InterruptGuard::~InterruptGuard() {
    sigaction(SIGINT, &g_old_int, nullptr);
    if (mode_ == Mode::command) sigaction(SIGTERM, &g_old_term, nullptr);
    if (mode_ == Mode::host) g_signal = 0; // read by the host before; no later call may see it
}

bool InterruptGuard::requested() {
    return g_signal.load(std::memory_order_relaxed) != 0;
}
int InterruptGuard::signal_number() {
    return g_signal.load(std::memory_order_relaxed);
}

void InterruptGuard::stop_if_requested(const std::string& stage) {
    if (requested()) throw Interrupted(stage, signal_number());
}

Interrupted::Interrupted(const std::string& stage, int sig)
    : std::runtime_error("interrupted by signal " + std::to_string(sig) + " during " + stage +
                         "; nothing was written"),
      signal_number(sig) {}

} // namespace tumble::io
