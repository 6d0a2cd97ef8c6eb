#include "app/run/progress.h"

#include <cstdio>
#include <unistd.h>

namespace tumble::app {

Progress::Progress(std::string label, std::int64_t total, bool quiet)
    : label_(std::move(label)), total_(total), enabled_(!quiet && isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()), last_(start_) {}

Progress::~Progress() {
    finish();
}

void Progress::update(std::int64_t done) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (done < total_ && now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    draw(done);
}

void Progress::draw(std::int64_t done) {
    const int width = 30;
    const double frac = total_ > 0 ? static_cast<double>(done) / total_ : 1.0;
    const int filled = static_cast<int>(frac * width);
    char bar[width + 1];
    for (int k = 0; k < width; ++k) bar[k] = k < filled ? '#' : '.';
    bar[width] = '\0';
    const double secs = std::chrono::duration<double>(last_ - start_).count();
    const double rate = secs > 0.0 ? done / secs : 0.0;
    const double eta = rate > 0.0 ? (total_ - done) / rate : 0.0;
    std::fprintf(stderr, "\r%s [%s] %3d%%  %lld/%lld  %.1f/s  ETA %.0fs \033[K", label_.c_str(),
                 bar, static_cast<int>(frac * 100.0), static_cast<long long>(done),
                 static_cast<long long>(total_), rate, eta);
    std::fflush(stderr);
    drawn_ = true;
}

void Progress::finish() {
    if (!drawn_) return;
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
    drawn_ = false;
}

} // namespace tumble::app
