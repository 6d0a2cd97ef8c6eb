// Tumble beside a peer engine on the same scenes (issue 28): ODE 0.16 (Debian's libode-dev,
// quickstep) and Tumble run the shifted sphere rain of issue 4 (physics/scenes/sphere_rain.h) at
// N = 1000 and 8000 and a column of 10 boxes (physics/scenes/contact_scenes.h), the same bodies,
// step (1/240 s) and duration, judged by the same code on the final state. Built only where ODE is
// found; a benchmark, never a test or a dependency of `tumble`. Run by scripts/bench-peers.sh.
//
// Cases, per scene:
//   ode                  ODE quickstep, 20 iterations, ERP 0.2, CFM 1e-5 (its defaults), hash space
//   tumble               Tumble at its defaults (effort on demand, docs/contacts.md)
//   tumble/threads:2     the same on two threads, by the wall clock; its final state must have the
//                        single-threaded run's bits (hash compared)
//   tumble/480x1         fixed settings: 2 substeps of 1/480 s, one solve and one relax sweep
//   tumble/1440x3        fixed settings: the defaults of issue 13 (6 substeps, 3 solve and 2 relax)
// Repetitions are interleaved (every case once, then again) so that a busy spell of the shared
// machine hits all cases alike; each case reports its median. One thread is timed by the thread's
// CPU time, two threads by the wall clock (and compared with one thread's wall clock).
//
//   peers_bench [--reps1000=5] [--reps8000=3] [--reps_stack=3] [--only=rain1000,rain8000,stack10]
//               [--csv=FILE] [--space=hash|sap] [--tolerances=MM,MM,...]
// --tolerances adds effort on demand at these contact tolerances (mm) to every scene.
#include "bench/peers/ode_world.h"
#include "bench/peers/peer_cases.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace tumble::bench;

int main(int argc, char** argv) {
    Options opt;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&](const char* key) -> const char* {
            const std::size_t n = std::strlen(key);
            return a.compare(0, n, key) == 0 ? argv[i] + n : nullptr;
        };
        if (const char* v = value("--reps1000="))
            opt.reps[0] = std::atoi(v);
        else if (const char* v = value("--reps8000="))
            opt.reps[1] = std::atoi(v);
        else if (const char* v = value("--reps_stack="))
            opt.reps[2] = std::atoi(v);
        else if (const char* v = value("--only="))
            opt.only = v;
        else if (const char* v = value("--csv="))
            opt.csv = v;
        else if (const char* v = value("--tolerances=")) {
            std::istringstream list(v);
            for (std::string mm; std::getline(list, mm, ',');) {
                char* end = nullptr;
                const double x = std::strtod(mm.c_str(), &end);
                if (mm.empty() || *end != '\0' || !(x > 0)) {
                    std::fprintf(stderr,
                                 "peers_bench: --tolerances: '%s' is not a positive length "
                                 "in mm\n",
                                 mm.c_str());
                    return 2;
                }
                opt.tolerances.push_back(1e-3 * x);
            }
        } else if (const char* v = value("--space="))
            opt.space = std::string(v) == "hash" ? OdeSpace::Hash : OdeSpace::SweepAndPrune;
        else {
            std::fprintf(stderr, "peers_bench: unknown argument %s\n", argv[i]);
            return 2;
        }
    }
    return run_peers(opt);
}
