#include "app/run/interrupt.h"

#include <atomic>
#include <csignal>
#include <unistd.h>

namespace tumble::app {
namespace {

// Signal handlers may only touch lock-free atomics; this is the one piece of process-wide
// state in Tumble, and it exists because signals are process-wide.
std::atomic<int> g_signal{0};
struct sigaction g_old_int, g_old_term;

extern "C" void on_signal(int sig) {
    if (g_signal.exchange(sig) != 0) _exit(128 + sig); // second signal: leave now
}

} // namespace

InterruptGuard::InterruptGuard() {
    g_signal = 0;
    struct sigaction sa {};
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &g_old_int);
    sigaction(SIGTERM, &sa, &g_old_term);
}

InterruptGuard::~InterruptGuard() {
    sigaction(SIGINT, &g_old_int, nullptr);
    sigaction(SIGTERM, &g_old_term, nullptr);
}

bool InterruptGuard::requested() {
    return g_signal.load(std::memory_order_relaxed) != 0;
}
int InterruptGuard::signal_number() {
    return g_signal.load(std::memory_order_relaxed);
}

} // namespace tumble::app
