// The verification table of `tumble study --auto` (auto_check.h): report.md's section and auto.csv.
#include "app/study/auto_check.h"
#include "app/study/report.h"

#include <cstdio>

namespace tumble::app::study {
namespace {

std::string percent(int n, int of) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%d / %d (%.0f%%)", n, of, of > 0 ? 100.0 * n / of : 0.0);
    return buf;
}

std::string fixed(double v, const char* format) {
    char buf[48];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

const char* yes(bool b) {
    return b ? "yes" : "**no**";
}

} // namespace

std::string auto_markdown(const std::vector<AutoCase>& cases) {
    const AutoSummary s = summarise(cases);
    std::string md = "## Accuracy on demand: `auto` against the exact answers\n\n";
    md += "For every problem with an exact or closed-form reference and each tolerance, `auto` "
          "planned the run (pilot runs with the step-doubling estimate, docs/accuracy.md); the "
          "chosen run was then compared with the reference at the sample times. *estimate* and "
          "*true* are the largest over the samples and bodies of max(rotation in rad, position "
          "in m). Cost ratios are against the cheapest grid row whose true error met the "
          "tolerance: by the planner's cost model and by this run's measured ns / body-step.\n\n";
    md += "Over the " + std::to_string(s.covered) +
          " cases the estimate covers (bodies in "
          "contact are not covered and are listed but not counted):\n\n";
    md += "- estimate within a factor of 3 of the true error: " + percent(s.within_3, s.covered) +
          " (target: at least 95%), counting as agreeing the cases where both are round-off "
          "(below 1e-12); strictly by the ratio: " +
          percent(s.within_3_strict, s.covered) + "\n";
    md += "- true error within the tolerance: " + percent(s.meets, s.covered) +
          " (target: at least 95%)\n";
    md += "- cost at most 2x the cheapest grid row that met it (cost model): " +
          percent(s.cost_within_2, s.covered) + "\n\n";
    md += "| problem | tolerance | chosen | steps | estimate | true | est / true | within 3x | "
          "meets | cheapest on the grid | cost / cheapest (model) | (measured) | pilots |\n";
    md += "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const AutoCase& c : cases) {
        md += "| " + c.problem + " | " + sci(c.tolerance, 0) + " | ";
        if (!c.found) {
            md += "none met it | | | | | | **no** | | | | " + std::to_string(c.pilots) + " |\n";
            continue;
        }
        md += c.integrator + " | " + std::to_string(c.steps) + " | " + sci(c.estimate) + " | " +
              sci(c.truth) + " | " + fixed(c.ratio, "%.2f") + " | " +
              (!c.covered    ? "not covered"
               : c.round_off ? "round-off"
                             : yes(c.within_3)) +
              " | " + yes(c.meets) + " | " + (c.cheapest.empty() ? "none met it" : c.cheapest) +
              " | " + fixed(c.cost_ratio_model, "%.2f") + " | " +
              fixed(c.cost_ratio_measured, "%.2f") + " | " + std::to_string(c.pilots) + " (" +
              fixed(c.pilot_seconds, "%.2f s") + ") |\n";
    }
    return md;
}

std::string auto_csv(const std::vector<AutoCase>& cases) {
    std::string csv = "problem,tolerance,covered,found,integrator,steps,dt,estimate,true_error,"
                      "ratio,within_3,meets,cheapest,cost_ratio_model,cost_ratio_measured,"
                      "pilots,pilot_seconds\n";
    for (const AutoCase& c : cases) {
        char buf[512];
        std::snprintf(buf, sizeof buf,
                      "%s,%.0e,%d,%d,%s,%lld,%.9g,%.6e,%.6e,%.4g,%d,%d,%s,%.4g,%.4g,%d,%.4g\n",
                      c.problem.c_str(), c.tolerance, c.covered, c.found, c.integrator.c_str(),
                      static_cast<long long>(c.steps), c.dt, c.estimate, c.truth, c.ratio,
                      c.within_3, c.meets, c.cheapest.c_str(), c.cost_ratio_model,
                      c.cost_ratio_measured, c.pilots, c.pilot_seconds);
        csv += buf;
    }
    return csv;
}

} // namespace tumble::app::study
