#!/usr/bin/env bash
# Tumble beside ODE on the same scenes, in one run (issue 28; bench/peers/peers_bench.cpp): the
# shifted sphere rain at N = 1000 and 8000 and a column of 10 boxes, ODE's quickstep (Debian's
# libode-dev, sweep-and-prune space) against Tumble at its defaults, on two threads, and at fixed
# settings (480x1, 1440x3), interleaved repetitions, medians, each case's ratio to ODE's steps per
# second and both penetrations. Keeps the results under bench/results/<machine>/ (machine =
# uname -n):
#   peers.csv        medians per case (the summary table)
#   peers_cpu.txt    what the machine is, when, and its load at the start and the end
#   scripts/bench-peers.sh [build-dir] [--reps1000=5] [--reps8000=3] [--reps_stack=3]
#                          [--only=rain1000,rain8000,stack10] [--space=sap|hash] [--tolerances=MM,...]
# Needs libode-dev (scripts/setup.sh installs it); without it bench/peers is not built and this
# script says so.
set -euo pipefail
cd "$(dirname "$0")/.."
build="build/release"
if [ $# -gt 0 ] && [ "${1#--}" = "$1" ]; then build="$1"; shift; fi
if [ ! -f "$build/build.ninja" ]; then
  cmake --preset release >&2
fi
if ! pkg-config --exists ode; then
  echo "bench-peers: ODE not found (install libode-dev: scripts/setup.sh); nothing to compare" >&2
  exit 1
fi
cmake --build "$build" --target peers_bench >&2
out="bench/results/$(uname -n)"
mkdir -p "$out"
scripts/machine-info.sh "ode: $(pkg-config --modversion ode)" > "$out/peers_cpu.txt"
"$build/bench/peers/peers_bench" --csv="$out/peers.csv" "$@"
echo "load average at end: $(cut -d' ' -f1-3 /proc/loadavg)" >> "$out/peers_cpu.txt"
