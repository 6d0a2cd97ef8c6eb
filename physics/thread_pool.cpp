#include "physics/thread_pool.h"

#include <algorithm>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define TUMBLE_PAUSE() _mm_pause()
#else
#define TUMBLE_PAUSE() std::this_thread::yield()
#endif

namespace tumble::physics {
namespace {
constexpr int kSpins = 1 << 15; // about 100 microseconds of spinning before sleeping
} // namespace

ThreadPool::ThreadPool(int threads) : size_(std::max(1, threads)) {
    for (int k = 1; k < size_; ++k) threads_.emplace_back([this, k] { worker_loop(k); });
}

ThreadPool::~ThreadPool() {
    stop_.store(true);
    generation_.fetch_add(1);
    { std::lock_guard<std::mutex> lock(mutex_); }
    wake_.notify_all();
    for (std::thread& t : threads_) t.join();
}

void ThreadPool::dispatch(void (*fn)(void*, int), void* ctx) {
    job_ = fn;
    ctx_ = ctx;
    done_.store(0, std::memory_order_relaxed);
    generation_.fetch_add(1); // publishes job_ and ctx_ (sequentially consistent)
    // A worker registers as a sleeper before its last look at the generation, under the mutex:
    // either it sees the new generation, or it is counted here and gets the notify.
    if (sleepers_.load() > 0) {
        { std::lock_guard<std::mutex> lock(mutex_); }
        wake_.notify_all();
    }
    fn(ctx, 0);
    const int others = size_ - 1;
    for (int spin = 0; done_.load(std::memory_order_acquire) != others; ++spin) {
        if (spin < kSpins) {
            TUMBLE_PAUSE();
        } else {
            std::this_thread::yield();
        }
    }
}

void ThreadPool::worker_loop(int k) {
    // Generation 0 is the pool's state at construction, before any job: reading the counter here
    // instead would miss a job dispatched before this thread got to run.
    std::uint32_t seen = 0;
    for (;;) {
        std::uint32_t now;
        int spin = 0;
        while ((now = generation_.load(std::memory_order_acquire)) == seen) {
            if (++spin < kSpins) {
                TUMBLE_PAUSE();
                continue;
            }
            std::unique_lock<std::mutex> lock(mutex_);
            sleepers_.fetch_add(1);
            wake_.wait(lock, [&] { return generation_.load() != seen; });
            sleepers_.fetch_sub(1);
        }
        seen = now;
        if (stop_.load(std::memory_order_acquire)) return;
        job_(ctx_, k);
        done_.fetch_add(1, std::memory_order_acq_rel);
    }
}

} // namespace tumble::physics
