#include "bench/render/render_table.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <thread>

namespace tumble::bench {

void print_table(const std::vector<RenderRow>& rows, int repeats, double load) {
    std::printf("%-22s %-9s %-25s %-4s %6s | %9s %8s %8s | %10s | %9s %6s | %7s %7s\n", "case",
                "size", "options", "sink", "frames", "physics", "render", "output", "end-to-end",
                "null e2e", "ratio", "cpu", "null");
    std::printf("%-22s %-9s %-25s %-4s %6s | %9s %8s %8s | %10s | %9s %6s | %7s %7s\n", "", "", "",
                "", "", "fps", "fps", "fps", "fps", "fps", "", "ms/fr", "ms/fr");
    for (const RenderRow& r : rows) {
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

void append_csv(const std::string& path, const std::string& machine,
                const std::vector<RenderRow>& rows, double load) {
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
    for (const RenderRow& r : rows) {
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

std::string host_name() {
    char name[256] = {};
    gethostname(name, sizeof name - 1);
    return name[0] ? name : "unknown";
}

double load_average() {
    double load[1] = {0.0};
    return getloadavg(load, 1) == 1 ? load[0] : -1.0;
}

} // namespace tumble::bench
