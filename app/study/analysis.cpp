#include "app/study/analysis.h"
#include "physics/integrator.h"

#include <cmath>
#include <limits>

namespace tumble::app::study {

std::vector<OrderFit> fit_orders(const std::vector<Row>& rows) {
    std::vector<OrderFit> fits;
    for (std::size_t i = 0; i < rows.size();) {
        // Rows of one (problem, integrator) are contiguous (run_grid's order).
        std::size_t end = i;
        while (end < rows.size() && rows[end].problem == rows[i].problem &&
               rows[end].integrator == rows[i].integrator)
            ++end;
        OrderFit f{rows[i].problem, rows[i].integrator, rows[i].contacts ? 1 : rows[i].order, 0.0,
                   0};
        if (rows[i].exact_here) {
            // Nothing truncated: the errors are round-off, which grows with the number of steps
            // (finer steps, larger errors) and has no order; a slope fitted to it would be noise.
            f.theory = physics::kExactOrder;
            f.measured = std::numeric_limits<double>::quiet_NaN();
            fits.push_back(f);
            i = end;
            continue;
        }
        double sx = 0, sy = 0, sxx = 0, sxy = 0;
        for (std::size_t k = i; k < end; ++k) {
            const double e = headline_error(rows[k]);
            if (rows[k].diverged || !(e >= kFitMinError && e <= kFitMaxError)) continue;
            const double x = std::log(rows[k].dt), y = std::log(e);
            sx += x, sy += y, sxx += x * x, sxy += x * y, ++f.points;
        }
        const double n = f.points;
        f.measured = f.points >= 3 ? (n * sxy - sx * sy) / (n * sxx - sx * sx)
                                   : std::numeric_limits<double>::quiet_NaN();
        fits.push_back(f);
        i = end;
    }
    return fits;
}

bool reaches(const std::vector<Row>& rows, const Row& r, double target) {
    for (const Row& o : rows)
        if (o.problem == r.problem && o.integrator == r.integrator && o.dt <= r.dt &&
            (o.diverged || !(headline_error(o) <= target)))
            return false;
    return true;
}

std::vector<Recommendation> recommend(const std::vector<Row>& rows,
                                      const std::vector<std::string>& problems) {
    std::vector<Recommendation> out;
    for (const std::string& problem : problems)
        for (double target : kTargets) {
            Recommendation rec{problem, target, nullptr};
            for (const Row& r : rows)
                if (r.problem == problem && reaches(rows, r, target) &&
                    (!rec.row || r.cost_s < rec.row->cost_s))
                    rec.row = &r;
            out.push_back(rec);
        }
    return out;
}

} // namespace tumble::app::study
