#pragma once
// A Google Benchmark console reporter that also keeps, per benchmark, its median (or its single
// run, without repetitions): every user counter plus "wall_ms", the adjusted real time in the
// benchmark's unit. The benchmarks' summaries (integrators_bench.cpp, sphere_rain_summary.h)
// derive from it and print their tables in Finalize().
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <string>

namespace tumble::bench {

class MedianReporter : public benchmark::ConsoleReporter {
  public:
    explicit MedianReporter(std::string path) : path_(std::move(path)) {}

    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& r : runs) {
            const bool median = r.run_type == Run::RT_Aggregate && r.aggregate_name == "median";
            if (!median && r.run_type != Run::RT_Iteration) continue;
            Row& row = rows_[r.run_name.function_name];
            if (row.median && !median) continue;
            row.median = median;
            for (const auto& [name, counter] : r.counters) row.values[name] = counter.value;
            row.values["wall_ms"] = r.GetAdjustedRealTime();
        }
    }

  protected:
    // The kept value of `counter` for benchmark `run`; NaN when either is missing.
    double value(const std::string& run, const std::string& counter) const {
        const auto r = rows_.find(run);
        if (r == rows_.end()) return NAN;
        const auto c = r->second.values.find(counter);
        return c == r->second.values.end() ? NAN : c->second;
    }

    bool has(const std::string& run) const { return rows_.count(run) != 0; }

    bool any_median() const {
        for (const auto& [name, row] : rows_)
            if (row.median) return true;
        return false;
    }

    std::string path_; // where the summary CSV goes (empty: nowhere)

  private:
    struct Row {
        bool median = false;
        std::map<std::string, double> values;
    };
    std::map<std::string, Row> rows_;
};

} // namespace tumble::bench
