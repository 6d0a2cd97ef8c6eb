#include "app/regression/suite_runner.h"

#include "app/regression/golden_renderers.h"
#include "app/regression/image_judge.h"
#include "app/regression/scene_pass.h"
#include "app/regression/state_compare.h"
#include "app/run/render_frames.h"
#include "io/bad_input.h"
#include "io/interrupt.h"
#include "render/renderer.h"

#include <fnmatch.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <numeric>
#include <thread>

namespace tumble::app {
namespace {

bool matches(const std::string& pattern, const std::string& scene, const std::string& check) {
    return fnmatch(pattern.c_str(), check.c_str(), 0) == 0 ||
           fnmatch(pattern.c_str(), scene.c_str(), 0) == 0;
}

bool selected(const std::vector<std::string>& filters, const std::string& scene,
              const std::string& check, std::vector<bool>& used) {
    bool any = filters.empty();
    for (std::size_t f = 0; f < filters.size(); ++f)
        if (matches(filters[f], scene, check)) any = true, used[f] = true;
    return any;
}

std::string shell_word(const std::string& s) {
    if (!s.empty() && s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                          "0123456789_./-=:,+@%") == std::string::npos)
        return s;
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

// One scene's checks, drawn, sampled and judged; a run that fails (a divergence, no GL) fails
// every check of the scene with its message.
void run_scene(const Suite& suite, const SuiteScene& scene,
               const std::vector<const ImageCheck*>& images,
               const std::vector<const StateCheck*>& states, const GlIdentity& here,
               const GoldenRenderers& record, std::vector<CheckResult>& out) {
    for (const ImageCheck* c : images) {
        out.emplace_back().scene = &scene;
        out.back().image = c;
    }
    for (const StateCheck* c : states) {
        out.emplace_back().scene = &scene;
        out.back().state = c;
    }
    try {
        ScenePass pass = run_scene_pass(scene, images, states);
        for (std::size_t i = 0; i < images.size(); ++i) {
            CheckResult& r = out[i];
            const auto start = std::chrono::steady_clock::now();
            r.image_outcome.actual = std::move(pass.images[i]);
            judge_image(*images[i], here, record, r);
            r.seconds =
                pass.image_seconds[i] +
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        }
        for (std::size_t i = 0; i < states.size(); ++i) {
            CheckResult& r = out[images.size() + i];
            r.state_outcome = std::move(pass.states[i]);
            judge_states(*states[i], r);
        }
    } catch (const std::exception& e) {
        for (CheckResult& r : out) {
            r.passed = false;
            r.run_failed = true;
            r.summary = std::string("the run failed: ") + e.what();
        }
    }
    for (CheckResult& r : out) {
        if (r.passed) continue;
        if (r.run_failed) continue;
        r.update = update_command(suite, r.name());
        if (r.golden_missing) r.summary += "; create it with: " + r.update;
    }
}

} // namespace

Selection select_checks(const Suite& suite, const std::vector<std::string>& filters) {
    Selection s;
    std::vector<bool> used(filters.size(), false);
    for (const SuiteScene& scene : suite.scenes) {
        s.images.emplace_back();
        s.states.emplace_back();
        for (const ImageCheck& c : scene.images)
            if (selected(filters, scene.name, c.name, used)) s.images.back().push_back(&c);
        for (const StateCheck& c : scene.states)
            if (selected(filters, scene.name, c.name, used)) s.states.back().push_back(&c);
        s.count += s.images.back().size() + s.states.back().size();
    }
    for (std::size_t f = 0; f < filters.size(); ++f)
        if (!used[f])
            throw io::BadInput("--filter " + shell_word(filters[f]) + " selects no check of " +
                               suite.path.string() + " (patterns match check and scene names)");
    if (s.count == 0) throw io::BadInput(suite.path.string() + ": the suite has no check");
    return s;
}

std::string update_command(const Suite& suite, const std::string& check) {
    return "tumble test " + shell_word(suite.path.string()) + " --update --filter " +
           shell_word(check);
}

std::size_t SuiteRun::failed() const {
    return static_cast<std::size_t>(std::count_if(results.begin(), results.end(),
                                                  [](const CheckResult& r) { return !r.passed; }));
}

SuiteRun run_suite(const Suite& suite, const Selection& sel, int jobs) {
    const auto start = std::chrono::steady_clock::now();
    SuiteRun run;
    run.jobs = std::max(1, jobs);
    const std::size_t n = suite.scenes.size();
    const bool draws =
        std::any_of(sel.images.begin(), sel.images.end(), [](const auto& v) { return !v.empty(); });
    if (draws) {
        tune_allocator_for_rendering();
        const render::Renderer probe({16, 16, 1, false});
        run.gl = {probe.gl_renderer(), probe.gl_version()};
    }
    const GoldenRenderers record = GoldenRenderers::load(suite.goldens);
    // Largest scenes first, so that the last job to start is a short one.
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    auto cost = [&](std::size_t i) {
        const SuiteScene& s = suite.scenes[i];
        return double(s.scene.bodies.size()) * double(s.timeline.frames) *
               double(sel.images[i].size() + 1);
    };
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return cost(a) > cost(b); });
    std::vector<std::vector<CheckResult>> by_scene(n);
    run.scene_seconds.assign(n, 0.0);
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
        for (std::size_t k; (k = next++) < n;) {
            if (io::InterruptGuard::requested()) return; // the scenes running stop, no more start
            const std::size_t i = order[k];
            if (sel.images[i].empty() && sel.states[i].empty()) continue;
            const auto t0 = std::chrono::steady_clock::now();
            run_scene(suite, suite.scenes[i], sel.images[i], sel.states[i], run.gl, record,
                      by_scene[i]);
            run.scene_seconds[i] =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        }
    };
    std::vector<std::thread> threads;
    for (int t = 1; t < run.jobs; ++t) threads.emplace_back(worker);
    worker();
    for (std::thread& t : threads) t.join();
    run.interrupted = io::InterruptGuard::requested();
    for (auto& results : by_scene)
        for (CheckResult& r : results) run.results.push_back(std::move(r));
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return run;
}

} // namespace tumble::app
