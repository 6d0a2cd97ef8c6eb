#pragma once
// A state check's judgement: its sampled states against its golden trajectory (the CSV pair
// `tumble simulate` writes, app/run/trajectory_reader.h), quantity by quantity, each within its
// absolute tolerance. A failure names the body, the quantity, the first time it left the
// tolerance and by how much, and the largest deviation.
#include "app/regression/check_result.h"

namespace tumble::app {

// Fills result.state_outcome.series, passed, summary and details from the samples already in
// result.state_outcome. A golden that is missing or unreadable fails the check, saying so.
void judge_states(const StateCheck& check, CheckResult& result);

// |actual - golden| of one quantity, in its unit (orientation: the angle between, radians).
double deviation(StateQuantity q, const StateRow& actual, const StateRow& golden);
double deviation(StateQuantity q, const DiagnosticsRow& actual, const DiagnosticsRow& golden);

} // namespace tumble::app
