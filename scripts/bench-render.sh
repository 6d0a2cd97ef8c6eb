#!/usr/bin/env bash
# Runs the renderer benchmark (bench/render/render_bench, cases in bench/README.md) with 3 repeats
# per case and appends the medians to bench/results/<machine>/render.csv (machine = uname -n, or
# the first argument). Builds it in the release tree first if needed.
#   scripts/bench-render.sh [machine] [extra render_bench options, e.g. --quick or case names]
set -euo pipefail
cd "$(dirname "$0")/.."
machine="${1:-$(uname -n)}"
shift || true
if [ ! -f build/release/build.ninja ]; then
  cmake --preset release >&2
fi
cmake --build build/release --target render_bench >&2
out="bench/results/$machine"
mkdir -p "$out"
build/release/bench/render/render_bench --repeats 3 --machine "$machine" --csv "$out/render.csv" "$@"
