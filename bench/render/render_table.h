#pragma once
// The render benchmark's results: the table on stdout and the rows appended to a CSV
// (bench/results/<machine>/render.csv), with the machine's label and its load, since other work on
// a shared machine slows every wall-clock rate.
#include "bench/render/render_measure.h"

#include <string>
#include <vector>

namespace tumble::bench {

void print_table(const std::vector<RenderRow>& rows, int repeats, double load);

// Appends the rows (a header first when the file is new). Throws std::runtime_error when the file
// cannot be written.
void append_csv(const std::string& path, const std::string& machine,
                const std::vector<RenderRow>& rows, double load);

std::string host_name();
double load_average(); // the 1-minute load average, -1 when unknown

} // namespace tumble::bench
