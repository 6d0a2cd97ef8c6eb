// `tumble bench-render`: how fast frames go through the pipeline (app/run/pipeline.h), per stage
// and end to end, for a fixed list of cases. Each case runs `repeats` times into its real sink and
// `repeats` times into the null sink (same binary, same frames, interleaved so that a busy spell
// on the machine hits both alike); the table shows medians and the ratio of the two end-to-end
// rates, which says what the output costs beyond drawing. A benchmark, not a test: it asserts
// nothing, it measures.
#include "app/cli/failure.h"
#include "app/cli/render_setup.h"
#include "app/cli/subcommand.h"
#include "app/run/auto_camera.h"
#include "app/run/prepare_run.h"
#include "app/run/render_frames.h"
#include "io/bad_input.h"
#include "render/open_sink.h"

#include <cstdlib>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

namespace tumble::app {
namespace {

struct BenchRenderCommand {
    std::vector<std::string> cases; // names from the built-in list; empty: all
    int repeats = 3;
    std::string csv;     // append the table here
    std::string machine; // label for the CSV (default: the host name)
    bool quick = false;  // fewer frames per case
};

struct BenchCase {
    const char* name;
    const char* scene; // built-in scene name, or "spheres1000" (generated below)
    const char* sink;  // "mp4", "png" or "gif"
    bool preview;
    bool shadows, antialiasing;
    int width, height;
    int frames, quick_frames;
    // The effects of issue 14, each on or off (the scene's defaults: soft shadows and AO on).
    bool soft_shadows = true, ambient_occlusion = true, reflections = false;
    // Issue 16's overlays: charts of the book's energy and w_body, trails, Poinsot's construction.
    bool teaching = false;
};

// The targets of issue 5: the default demo at 720p with shadows and anti-aliasing (10 s at
// 60 fps), the same into PNG frames, a 1000-sphere scene with shadows, and the preview mode.
// Then the cost of each effect of issue 14 on the default demo, against `default-720p-hard`
// (hard shadows, no ambient occlusion: the picture before them), and GIF output.
constexpr BenchCase kCases[] = {
    {"default-720p-mp4", "default", "mp4", false, true, true, 1280, 720, 600, 120},
    {"default-720p-png", "default", "png", false, true, true, 1280, 720, 240, 60},
    {"spheres1000-720p", "spheres1000", "mp4", false, true, true, 1280, 720, 120, 30},
    {"spheres1000-720p-noaa", "spheres1000", "mp4", false, true, false, 1280, 720, 120, 30},
    {"default-preview", "default", "mp4", true, false, false, 640, 360, 600, 120},
    {"default-720p-hard", "default", "mp4", false, true, true, 1280, 720, 240, 60, false, false},
    {"default-720p-soft", "default", "mp4", false, true, true, 1280, 720, 240, 60, true, false},
    {"default-720p-ao", "default", "mp4", false, true, true, 1280, 720, 240, 60, false, true},
    {"default-720p-mirror", "default", "mp4", false, true, true, 1280, 720, 240, 60, true, true,
     true},
    {"default-480p-gif", "default", "gif", false, true, true, 854, 480, 240, 60},
    {"default-480p-mp4", "default", "mp4", false, true, true, 854, 480, 240, 60},
    {"default-720p-base", "default", "mp4", false, true, true, 1280, 720, 240, 60},
    {"default-720p-teach", "default", "mp4", false, true, true, 1280, 720, 240, 60, true, true,
     false, true},
};

// 1000 spheres in a 10 x 10 x 10 lattice above a ground, floating (gravity_scale 0) and each
// spinning about its own axis, drifting together so nothing ever touches. The camera orbits.
std::string spheres1000_json() {
    std::ostringstream s;
    s << R"json({"format_version": 1, "title": "1000 spheres (benchmark)",
  "world": {"duration": 10},
  "render": {"camera": {"position": [9, -12, 7], "target": [0, 0, 2.4], "fov_deg": 45,
                        "orbit": {"period": 40}},
             "light": {"direction": [-0.5, 0.4, -1.0], "ambient": 0.3}},
  "bodies": [{"name": "ground", "shape": {"type": "plane", "extent": 40}, "color": [0.82, 0.82, 0.8]})json";
    const char* colours[] = {"#c0392b", "#2e86c1", "#f1c40f", "#27ae60", "#8e44ad", "#e67e22"};
    for (int i = 0; i < 1000; ++i) {
        const int a = i % 10, b = (i / 10) % 10, c = i / 100;
        s << ",\n  {\"shape\": {\"type\": \"sphere\", \"radius\": 0.17}, \"gravity_scale\": 0, "
          << "\"position\": [" << -2.7 + 0.6 * a << ", " << -2.7 + 0.6 * b << ", " << 0.5 + 0.45 * c
          << "], \"velocity\": [0, 0, 0.02], \"angular_velocity\": [" << 0.3 * (a - 5) << ", "
          << 0.2 * (b - 5) << ", 1.5], \"color\": \"" << colours[(a + b + c) % 6] << "\"}";
    }
    s << "\n]}\n";
    return s.str();
}

Scene load_case_scene(const BenchCase& c) {
    if (std::string(c.scene) == "spheres1000") return load_scene(spheres1000_json(), "spheres1000");
    return load_scene_argument(c.scene);
}

struct Sample {
    PipelineStats stats;
};

// One run of a case into `output` (a file, a folder, or "null").
PipelineStats run_once(const BenchCase& c, int frames, const std::string& output) {
    Scene scene = load_case_scene(c);
    RenderCommand cmd;
    cmd.preview = c.preview;
    cmd.width = c.width;
    cmd.height = c.height;
    cmd.shadows = c.shadows;
    cmd.antialiasing = c.antialiasing;
    cmd.soft_shadows = c.soft_shadows;
    cmd.ambient_occlusion = c.ambient_occlusion;
    cmd.reflections = c.reflections;
    if (c.teaching) {
        cmd.chart = std::vector<std::string>{"energy", "w_body"};
        cmd.chart_body = "book";
        cmd.trails = true;
        cmd.poinsot = "book";
    }
    apply_render_overrides(cmd, scene);
    scene.duration = double(frames) / scene.render.fps;
    PreparedRun run = prepare_run(std::move(scene));
    frame_automatically(run.scene, run.timeline); // camera.auto: a pre-pass over the run
    const Timeline& tl = run.timeline;
    render::SinkOptions so;
    so.width = run.scene.render.width;
    so.height = run.scene.render.height;
    so.fps = run.scene.render.fps;
    so.preset = video_preset(cmd); // as `tumble render` would encode it
    auto sink = render::open_sink(output, so);
    const RunResult r = render_frames(run.scene, tl, run.sim, *sink, 0, tl.frames - 1, true);
    // Finishing is part of the run: the encoder's last frames, and for a GIF both of its
    // palette passes over the spooled frames.
    PipelineStats stats = r.stats;
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    sink->finish();
    stats.wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    stats.cpu += double(std::clock() - c0) / CLOCKS_PER_SEC;
    return stats;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct Row {
    const BenchCase* c;
    int frames, repeats;
    double physics, render, output, e2e, null_render, null_e2e;
    double cpu_ms, null_cpu_ms; // process CPU time per frame, every thread
    double ratio() const { return e2e > 0 ? null_e2e / e2e : 0.0; }
};

std::string options_label(const BenchCase& c) {
    std::string s = c.preview ? "preview" : "";
    auto add = [&s](const char* word) {
        if (!s.empty()) s += '+';
        s += word;
    };
    if (c.shadows) add(c.soft_shadows ? "soft-shadows" : "shadows");
    if (c.antialiasing) add("msaa4");
    if (c.ambient_occlusion && !c.preview) add("ao");
    if (c.reflections) add("mirror");
    if (c.teaching) add("teach");
    return s.empty() ? "plain" : s;
}

std::string host_name() {
    char name[256] = {};
    gethostname(name, sizeof name - 1);
    return name[0] ? name : "unknown";
}

// The 1-minute load average: other work on the machine slows every wall-clock rate.
double load_average() {
    double load[1] = {0.0};
    return getloadavg(load, 1) == 1 ? load[0] : -1.0;
}

void append_csv(const std::string& path, const std::string& machine, const std::vector<Row>& rows,
                double load) {
    const bool fresh = !std::filesystem::exists(path);
    if (const auto parent = std::filesystem::path(path).parent_path(); !parent.empty())
        std::filesystem::create_directories(parent);
    std::ofstream out(path, std::ios::app);
    if (fresh)
        out << "date,machine,load_1min,case,scene,width,height,options,sink,frames,repeats,"
               "physics_fps,render_fps,output_fps,end_to_end_fps,null_render_fps,"
               "null_end_to_end_fps,null_ratio,cpu_ms_per_frame,null_cpu_ms_per_frame\n";
    char date[32];
    const std::time_t now = std::time(nullptr);
    std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%S", std::localtime(&now));
    for (const Row& r : rows) {
        char line[512];
        std::snprintf(line, sizeof line,
                      "%s,%s,%.2f,%s,%s,%d,%d,%s,%s,%d,%d,%.1f,%.2f,%.2f,%.2f,%.2f,%.2f,%.3f,%.1f,"
                      "%.1f\n",
                      date, machine.c_str(), load, r.c->name, r.c->scene, r.c->width, r.c->height,
                      options_label(*r.c).c_str(), r.c->sink, r.frames, r.repeats, r.physics,
                      r.render, r.output, r.e2e, r.null_render, r.null_e2e, r.ratio(), r.cpu_ms,
                      r.null_cpu_ms);
        out << line;
    }
    if (!out) throw std::runtime_error("cannot write " + path);
}

std::vector<const BenchCase*> select_cases(const std::vector<std::string>& names) {
    std::vector<const BenchCase*> cases;
    for (const BenchCase& c : kCases)
        if (names.empty() || std::find(names.begin(), names.end(), c.name) != names.end())
            cases.push_back(&c);
    if (cases.size() < std::max<std::size_t>(1, names.size())) {
        std::string all;
        for (const BenchCase& c : kCases) all += std::string(all.empty() ? "" : ", ") + c.name;
        throw io::BadInput("unknown benchmark case; cases: " + all);
    }
    return cases;
}

// A folder of this process's outputs under the temporary directory, removed when done.
struct ScratchDir {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("tumble-bench-" + std::to_string(::getpid()));
    ~ScratchDir() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
};

// `repeats` runs of one case into its real sink, each followed by one into the null sink.
Row measure(const BenchCase& c, const BenchRenderCommand& cmd, const ScratchDir& scratch) {
    const int frames = cmd.quick ? c.quick_frames : c.frames;
    std::vector<double> physics, render, output, e2e, null_render, null_e2e, cpu, null_cpu;
    for (int i = 0; i < cmd.repeats; ++i) {
        std::filesystem::remove_all(scratch.path);
        std::filesystem::create_directories(scratch.path);
        const std::string out = std::string(c.sink) == "png"
                                    ? (scratch.path / "frames/").string()
                                    : (scratch.path / (std::string("bench.") + c.sink)).string();
        const PipelineStats real = run_once(c, frames, out);
        const PipelineStats null = run_once(c, frames, "null");
        physics.push_back(real.physics.rate());
        render.push_back(real.render.rate());
        output.push_back(real.output.rate());
        e2e.push_back(real.rate());
        null_render.push_back(null.render.rate());
        null_e2e.push_back(null.rate());
        cpu.push_back(1e3 * real.cpu / double(std::max<std::int64_t>(1, real.frames)));
        null_cpu.push_back(1e3 * null.cpu / double(std::max<std::int64_t>(1, null.frames)));
        std::fprintf(stderr, "bench: %s run %d/%d: %.1f fps (null sink %.1f fps)\n", c.name, i + 1,
                     cmd.repeats, real.rate(), null.rate());
    }
    return {&c,
            frames,
            cmd.repeats,
            median(physics),
            median(render),
            median(output),
            median(e2e),
            median(null_render),
            median(null_e2e),
            median(cpu),
            median(null_cpu)};
}

void print_table(const std::vector<Row>& rows, int repeats, double load) {
    std::printf("%-22s %-9s %-25s %-4s %6s | %9s %8s %8s | %10s | %9s %6s | %7s %7s\n", "case",
                "size", "options", "sink", "frames", "physics", "render", "output", "end-to-end",
                "null e2e", "ratio", "cpu", "null");
    std::printf("%-22s %-9s %-25s %-4s %6s | %9s %8s %8s | %10s | %9s %6s | %7s %7s\n", "", "", "",
                "", "", "fps", "fps", "fps", "fps", "fps", "", "ms/fr", "ms/fr");
    for (const Row& r : rows) {
        char size[32];
        std::snprintf(size, sizeof size, "%dx%d", r.c->width, r.c->height);
        std::printf("%-22s %-9s %-25s %-4s %6d | %9.1f %8.1f %8.1f | %10.1f | %9.1f %6.2f | %7.1f "
                    "%7.1f\n",
                    r.c->name, size, options_label(*r.c).c_str(), r.c->sink, r.frames, r.physics,
                    r.render, r.output, r.e2e, r.null_e2e, r.ratio(), r.cpu_ms, r.null_cpu_ms);
    }
    std::printf("%s of %d run%s; stage rates are frames per second of busy time (queue waits "
                "excluded); ratio = null-sink end-to-end / real end-to-end; cpu = process CPU "
                "time per frame, all threads; 1-minute load average %.2f on %u cores\n",
                repeats == 1 ? "values" : "medians", repeats, repeats == 1 ? "" : "s", load,
                std::thread::hardware_concurrency());
}

int run_bench_render(const BenchRenderCommand& cmd) {
    const std::vector<const BenchCase*> cases = select_cases(cmd.cases);
    std::vector<Row> rows;
    {
        const ScratchDir scratch;
        for (const BenchCase* c : cases) rows.push_back(measure(*c, cmd, scratch));
    }
    const double load = load_average();
    print_table(rows, cmd.repeats, load);
    if (!cmd.csv.empty()) {
        append_csv(cmd.csv, cmd.machine.empty() ? host_name() : cmd.machine, rows, load);
        std::printf("appended to %s\n", cmd.csv.c_str());
    }
    return kOk;
}

} // namespace

Subcommand add_bench_render_command(CLI::App& app) {
    auto cmd = std::make_shared<BenchRenderCommand>();
    CLI::App* b = app.add_subcommand(
        "bench-render", "frame rates per pipeline stage and end to end, against a null sink");
    b->add_option("cases", cmd->cases, "cases to run (default: all; see bench/README.md)");
    b->add_option("--repeats", cmd->repeats, "runs per case; the table shows medians (default 3)")
        ->check(CLI::PositiveNumber);
    b->add_option("--csv", cmd->csv, "append the results to this CSV file");
    b->add_option("--machine", cmd->machine, "machine label in the CSV (default: host name)");
    b->add_flag("--quick", cmd->quick, "fewer frames per case");
    return {[b] { return b->parsed(); }, [cmd] { return run_bench_render(*cmd); }};
}

} // namespace tumble::app
