#include "physics/effort_tally.h"

#include <algorithm>
#include <cstdio>

namespace tumble::physics {

void EffortTally::add(const ContactStats& stats) {
    ++steps;
    const ContactEffort& e = stats.effort;
    if (e.islands == 0) return;
    substeps_min = solved_steps == 0 ? e.substeps_min : std::min(substeps_min, e.substeps_min);
    ++solved_steps;
    islands += e.islands;
    islands_max = std::max(islands_max, e.islands);
    bodies += e.bodies;
    body_substeps += e.body_substeps;
    points += stats.points;
    point_sweeps += e.point_sweeps;
    substeps_max = std::max(substeps_max, e.substeps_max);
    sweeps_max = std::max(sweeps_max, e.sweeps_max);
    capped_substeps += e.capped_substeps;
}

std::string EffortTally::describe(const ContactSettings& settings, double h) const {
    char text[512];
    const double per_point = points > 0 ? point_sweeps / points : 0.0;
    if (fixed_effort(settings)) {
        const int n = substep_count(settings, h);
        std::snprintf(text, sizeof text,
                      "contact effort fixed by the scene: %d substep%s, %d solve and %d relax "
                      "sweeps in every island (%.3g sweeps per contact point per step)",
                      n, n == 1 ? "" : "s", iteration_count(settings), settings.relax_iterations,
                      per_point);
        return text;
    }
    if (solved_steps == 0) {
        std::snprintf(text, sizeof text,
                      "contact effort on demand (tolerance %.3g mm): no contact to solve in %lld "
                      "step%s",
                      1e3 * settings.tolerance, steps, steps == 1 ? "" : "s");
        return text;
    }
    std::snprintf(text, sizeof text,
                  "contact effort on demand (tolerance %.3g mm) over %lld of %lld steps: %.3g "
                  "islands per step (at most %d), substeps per island %d..%d (%.3g per body in "
                  "contact), %.3g sweeps per contact point per step, at most %d solve and relax "
                  "sweeps per substep%s",
                  1e3 * settings.tolerance, solved_steps, steps, islands / solved_steps,
                  islands_max, substeps_min, substeps_max, bodies > 0 ? body_substeps / bodies : 0,
                  per_point, sweeps_max,
                  capped_substeps > 0 ? "; islands that asked for more than 64 substeps: " : "");
    std::string out = text;
    if (capped_substeps > 0) out += std::to_string(capped_substeps) + " island-steps (capped)";
    return out;
}

} // namespace tumble::physics
