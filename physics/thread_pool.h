#pragma once
// A fixed team of threads for the contact stage, run fork-join: run(fn) calls fn(k) on worker k
// = 0 .. size() - 1 (worker 0 is the calling thread) and returns when all are done. Work is split
// into fixed contiguous ranges by worker index, never claimed dynamically, and every worker writes
// only its own outputs; so results do not depend on timing, and with the same split into ranges
// they are bit-identical for any thread count (determinism by construction).
//
// Idle workers spin briefly (a step dispatches a few hundred jobs, microseconds apart), then sleep
// on a condition variable, so a pool costs nothing while the program renders or writes files.
// (Not std::atomic::wait: with GCC 12's libstdc++ a worker slept through a notify_all here.)
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace tumble::physics {

class ThreadPool {
  public:
    explicit ThreadPool(int threads);
    ~ThreadPool();
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;

    // Workers that run() uses: the team, or 1 inside a Serial section.
    int size() const { return serial_ > 0 ? 1 : size_; }

    // While a Serial section exists, run() and for_ranges() do all the work on the calling
    // thread: for steps too small to pay for the hand-offs (ContactSettings::parallel_min_bodies).
    // The results are the same bits either way.
    class Serial {
      public:
        Serial(ThreadPool& pool, bool engage) : pool_(engage ? &pool : nullptr) {
            if (pool_) ++pool_->serial_;
        }
        ~Serial() {
            if (pool_) --pool_->serial_;
        }
        Serial(const Serial&) = delete;
        Serial& operator=(const Serial&) = delete;

      private:
        ThreadPool* pool_;
    };

    // fn(int worker); must not throw.
    template <class F>
    void run(F&& fn) {
        if (size() == 1) return fn(0);
        dispatch(&call<F>, &fn);
    }

    // [begin, end) of worker k when n items are split into size() contiguous ranges.
    static void range(int n, int workers, int k, int& begin, int& end) {
        begin = static_cast<int>(static_cast<std::int64_t>(n) * k / workers);
        end = static_cast<int>(static_cast<std::int64_t>(n) * (k + 1) / workers);
    }

    // fn(begin, end, worker) over n items; below `grain` items worker 0 does everything (the
    // result is the same either way; this only saves the hand-off).
    template <class F>
    void for_ranges(int n, int grain, F&& fn) {
        if (size() == 1 || n < grain) return fn(0, n, 0);
        run([&](int k) {
            int b, e;
            range(n, size_, k, b, e);
            fn(b, e, k);
        });
    }

  private:
    template <class F>
    static void call(void* f, int k) {
        (*static_cast<F*>(f))(k);
    }
    void dispatch(void (*fn)(void*, int), void* ctx);
    void worker_loop(int k);

    int size_;
    int serial_ = 0; // Serial sections alive (only the calling thread touches it)
    std::vector<std::thread> threads_;
    void (*job_)(void*, int) = nullptr;
    void* ctx_ = nullptr;
    std::atomic<std::uint32_t> generation_{0};
    std::atomic<int> done_{0};
    std::atomic<bool> stop_{false};
    std::atomic<int> sleepers_{0};
    std::mutex mutex_;
    std::condition_variable wake_;
};

} // namespace tumble::physics
