#pragma once
// The most memory this process has held at once (its peak resident set, from getrusage(2)),
// printed in the run summaries of render and simulate so users can size their machines; the
// figures for large scenes are measured by bench/peak_memory.sh.
#include <cstdint>
#include <string>

namespace tumble::app {

std::int64_t peak_memory_bytes();
std::string describe_peak_memory(); // "peak memory 412.3 MiB"

} // namespace tumble::app
