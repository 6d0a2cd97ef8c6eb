#!/usr/bin/env bash
# The Python module against the command line (bench/python_bench.py: simulate's cost and the
# frame rate of rendering into NumPy, medians of interleaved repeats, the two ratios printed) and
# appends the medians to bench/results/<machine>/python.csv (machine = uname -n, or the first
# argument). Builds `tumble` and the module first. Exit 1 when a ratio misses issue 29's bound.
#   scripts/bench-python.sh [machine] [extra options, e.g. --repeats 7]
set -euo pipefail
cd "$(dirname "$0")/.."
machine="${1:-$(uname -n)}"
shift || true
if [ ! -f build/release/build.ninja ]; then
  cmake --preset release >&2
fi
cmake --build build/release --target tumble tumble_python >&2
out="bench/results/$machine"
mkdir -p "$out"
/usr/bin/python3 bench/python_bench.py build/release/app/tumble build/release/python \
  --machine "$machine" --csv "$out/python.csv" "$@"
