#pragma once
// The summary of bench/sphere_rain_bench.cpp: medians of every case in one table (also written
// as CSV with --summary=FILE), the two-core speed-up, and issue 4's targets, each judged on
// numbers measured in this run.
#include "bench/median_reporter.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>

namespace tumble::bench {

class RainSummary : public MedianReporter {
  public:
    using MedianReporter::MedianReporter;

    void Finalize() override {
        ConsoleReporter::Finalize();
        std::string csv = "case,N,steps_per_s,us_per_body_step,us_per_contact,"
                          "us_per_contact_iteration,contacts_end,manifolds_end,"
                          "max_penetration_mm,kinetic_energy_J,outside,speedup_2_threads,"
                          "bit_identical_to_1_thread,time_vs_480x1\n";
        for (const int n : {1000, 8000}) {
            const std::string base = "rain/" + std::to_string(n);
            const double single = value(base + "/shifted/threads:1", "wall_ms");
            const std::string legacy = base + "/shifted_480x1/threads:1";
            for (const char* c : {"/shifted/threads:1", "/shifted/threads:2", "/columns/threads:1",
                                  "/shifted_480x1/threads:1"}) {
                const std::string name = base + c;
                if (!has(name)) continue;
                const bool two = std::string(c) == "/shifted/threads:2";
                char line[512];
                std::snprintf(line, sizeof line,
                              "%s,%d,%.1f,%.3f,%.4f,%.5f,%.0f,%.0f,%.3f,%.4g,%.0f,%s,%s,%s\n",
                              name.c_str(), n, value(name, "steps_per_s"),
                              value(name, "us_per_body_step"), value(name, "us_per_contact"),
                              value(name, "us_per_contact_iteration"), value(name, "contacts"),
                              value(name, "manifolds"), value(name, "max_penetration_mm"),
                              value(name, "kinetic_energy_J"), value(name, "outside"),
                              two ? fmt(single / value(name, "wall_ms")).c_str() : "",
                              two ? (value(name, "identical") == 1.0 ? "yes" : "NO") : "",
                              std::string(c) == "/shifted/threads:1" && has(legacy)
                                  ? fmt(value(name, "wall_ms") / value(legacy, "wall_ms")).c_str()
                                  : "");
                csv += line;
            }
        }
        const double assembled = value("free_flight/assembled", "ns_per_body_step");
        const double forced = value("free_flight/contacts_forced", "ns_per_body_step");
        std::printf("\nSummary (%s; one thread by CPU time, two by wall clock):\n%s",
                    any_median() ? "medians" : "single runs, no repetitions", csv.c_str());
        std::printf("\nFree flight, 2 bodies that cannot touch: %.1f ns per body-step as assembled "
                    "(no contact stage), %.1f with the stage forced on (%.2fx)\n",
                    assembled, forced, forced / assembled);
        targets();
        if (!path_.empty()) std::ofstream(path_) << csv;
    }

  private:
    static std::string fmt(double v) {
        char text[32];
        std::snprintf(text, sizeof text, "%.2f", v);
        return text;
    }

    void targets() const {
        const std::string a = "rain/1000/shifted/threads:1", b = "rain/8000/shifted/threads:1";
        const double sa = value(a, "steps_per_s"), sb = value(b, "steps_per_s");
        const double ca = value(a, "us_per_contact"), cb = value(b, "us_per_contact");
        const double ia = value(a, "us_per_contact_iteration");
        const double ib = value(b, "us_per_contact_iteration");
        const double pen =
            std::fmax(value(a, "max_penetration_mm"), value(b, "max_penetration_mm"));
        const double out = value(a, "outside") + value(b, "outside");
        auto verdict = [](bool ok) { return ok ? "met" : "MISSED"; };
        std::printf("\nIssue 4 targets (shifted scene, one thread):\n");
        std::printf("  N = 1000: %.0f steps/s (target >= 1000): %s\n", sa, verdict(sa >= 1000));
        std::printf("  N = 8000: %.1f steps/s (target >= 40): %s\n", sb, verdict(sb >= 40));
        std::printf(
            "  cost per contact 8000/1000: %.2fx, per contact-iteration %.2fx (target < 1.5x): "
            "%s\n",
            cb / ca, ib / ia, verdict(cb / ca < 1.5 && ib / ia < 1.5));
        std::printf("  max penetration at the end: %.3f mm (target < 1 mm): %s\n", pen,
                    verdict(pen < 1.0));
        std::printf("  spheres outside the box or below the floor: %.0f (target 0): %s\n", out,
                    verdict(out == 0));
    }
};

} // namespace tumble::bench
