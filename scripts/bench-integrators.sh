#!/usr/bin/env bash
# Runs the integrator benchmark (bench/integrators_bench.cpp) with 5 repetitions and keeps the
# results under bench/results/<machine>/ (machine = uname -n):
#   integrators.csv          Google Benchmark's CSV: mean, median, stddev, cv of every benchmark
#   integrators_summary.csv  medians per integrator with the ratios measured in the same run
#   cpu.txt                  what the machine is (/proc/cpuinfo), and when
#   scripts/bench-integrators.sh [build-dir]    (default build/release, configured if missing)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build/release}"
if [ ! -f "$build/build.ninja" ]; then
  cmake --preset release >&2
fi
cmake --build "$build" --target integrators_bench >&2
out="bench/results/$(uname -n)"
mkdir -p "$out"
scripts/machine-info.sh "timings: CPU-time medians" > "$out/cpu.txt"
"$build/bench/integrators_bench" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  --benchmark_out="$out/integrators.csv" --benchmark_out_format=csv \
  --summary="$out/integrators_summary.csv"
