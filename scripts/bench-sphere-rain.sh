#!/usr/bin/env bash
# Runs the sphere-rain benchmark of issue 4 (bench/sphere_rain_bench.cpp) and keeps the results
# under bench/results/<machine>/ (machine = uname -n):
#   sphere_rain.csv          medians per case: steps per second, us per body-step, per contact and
#                            per contact-iteration, contacts, penetration, kinetic energy and
#                            spheres outside at the end, the 2-core speed-up, bits identical or not
#   sphere_rain_runs.json    Google Benchmark's JSON of every case (mean, median, stddev, cv)
#   sphere_rain_cpu.txt      what the machine is, when, and its load at the start
# The summary table and the verdict on each of the issue's targets are printed at the end.
#   scripts/bench-sphere-rain.sh [build-dir] [--reps1000=5] [--reps8000=3]
#                                (default build/release, configured if missing)
set -euo pipefail
cd "$(dirname "$0")/.."
build="build/release"
if [ $# -gt 0 ] && [ "${1#--}" = "$1" ]; then build="$1"; shift; fi
if [ ! -f "$build/build.ninja" ]; then
  cmake --preset release >&2
fi
cmake --build "$build" --target sphere_rain_bench >&2
out="bench/results/$(uname -n)"
mkdir -p "$out"
scripts/machine-info.sh > "$out/sphere_rain_cpu.txt"
"$build/bench/sphere_rain_bench" --benchmark_report_aggregates_only=true \
  --benchmark_out="$out/sphere_rain_runs.json" --benchmark_out_format=json \
  --summary="$out/sphere_rain.csv" "$@"
