#include "app/run/pipeline.h"

#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

#include <sys/resource.h>

namespace tumble::app {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

// CPU time of the process so far, user + system, every thread. On a machine shared with other
// work the wall-clock rates vary with the load; the CPU time per frame does much less.
double process_cpu_seconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    auto s = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
    return s(u.ru_utime) + s(u.ru_stime);
}

// A FIFO of at most `capacity` items between two threads. close() wakes every waiter: push then
// fails, pop drains what is left and then fails.
template <class T>
class Channel {
  public:
    explicit Channel(std::size_t capacity) : capacity_(capacity) {}

    bool push(T&& item) {
        std::unique_lock lock(mutex_);
        not_full_.wait(lock, [this] { return closed_ || items_.size() < capacity_; });
        if (closed_) return false;
        items_.push_back(std::move(item));
        not_empty_.notify_one();
        return true;
    }

    std::optional<T> pop() {
        std::unique_lock lock(mutex_);
        not_empty_.wait(lock, [this] { return closed_ || !items_.empty(); });
        if (items_.empty()) return std::nullopt;
        std::optional<T> item(std::move(items_.front()));
        items_.pop_front();
        not_full_.notify_one();
        return item;
    }

    void close() {
        std::lock_guard lock(mutex_);
        closed_ = true;
        not_empty_.notify_all();
        not_full_.notify_all();
    }

  private:
    std::size_t capacity_;
    std::deque<T> items_;
    bool closed_ = false;
    std::mutex mutex_;
    std::condition_variable not_empty_, not_full_;
};

// The first exception of any stage; the others are consequences (closed queues) and are dropped.
class FirstError {
  public:
    void set(std::exception_ptr e) {
        std::lock_guard lock(mutex_);
        if (!error_) error_ = e;
    }
    void rethrow() {
        if (error_) std::rethrow_exception(error_);
    }

  private:
    std::mutex mutex_;
    std::exception_ptr error_;
};

// The pipeline's queues. Forward queues carry frames; return queues bring their buffers back for
// reuse. Each return queue starts with every buffer, so the forward queues never hold more than n.
struct Queues {
    explicit Queues(std::size_t n) : views(n), free_views(n), images(n), free_images(n) {
        for (std::size_t i = 0; i < n; ++i) {
            free_views.push({});
            free_images.push({});
        }
    }
    // Records the first exception and wakes every stage so that each one stops.
    void fail(std::exception_ptr e) {
        error.set(e);
        close_all();
    }
    void close_all() { views.close(), free_views.close(), images.close(), free_images.close(); }

    Channel<render::SceneView> views, free_views;
    Channel<render::Image> images, free_images;
    FirstError error;
};

void physics_stage(const PipelineStages& stages, Queues& q, StageStats& stats) {
    try {
        while (auto view = q.free_views.pop()) {
            const auto t = Clock::now();
            const bool more = stages.produce(*view);
            stats.busy += seconds_since(t);
            if (!more) break;
            ++stats.frames;
            if (!q.views.push(std::move(*view))) break;
        }
    } catch (...) {
        q.fail(std::current_exception());
    }
    q.views.close(); // no more frames: the render stage drains and stops
}

void render_stage(const PipelineStages& stages, Queues& q, StageStats& stats) {
    try {
        std::unique_ptr<render::Renderer> renderer = stages.make_renderer();
        while (auto view = q.views.pop()) {
            auto image = q.free_images.pop();
            if (!image) break;
            const auto t = Clock::now();
            renderer->draw(*view, *image);
            stats.busy += seconds_since(t);
            ++stats.frames;
            q.free_views.push(std::move(*view));
            if (!q.images.push(std::move(*image))) break;
        }
    } catch (...) {
        q.fail(std::current_exception());
    }
    q.images.close();
    q.free_views.close(); // the producer may be waiting for a buffer that will never come
}

void output_stage(const PipelineStages& stages, Queues& q, StageStats& stats) {
    try {
        while (auto image = q.images.pop()) {
            const auto t = Clock::now();
            stages.consume(*image);
            stats.busy += seconds_since(t);
            ++stats.frames;
            q.free_images.push(std::move(*image));
        }
    } catch (...) {
        q.fail(std::current_exception());
    }
}

} // namespace

PipelineStats run_pipeline(const PipelineStages& stages, int depth) {
    Queues q(std::size_t(depth < 1 ? 1 : depth));
    PipelineStats stats;
    const auto t0 = Clock::now();
    const double cpu0 = process_cpu_seconds();
    std::thread physics([&] { physics_stage(stages, q, stats.physics); });
    std::thread render([&] { render_stage(stages, q, stats.render); });
    output_stage(stages, q, stats.output); // on the calling thread
    q.close_all();
    physics.join();
    render.join();
    stats.wall = seconds_since(t0);
    stats.cpu = process_cpu_seconds() - cpu0;
    stats.frames = stats.output.frames;
    q.error.rethrow();
    return stats;
}

} // namespace tumble::app
