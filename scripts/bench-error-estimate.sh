#!/usr/bin/env bash
# The cost of --error-estimate (issue 17; docs/error-estimate.md): `tumble simulate` of each case
# with and without it, interleaved, `reps` times; medians of the CPU time (user + sys) and of the
# wall time, and their ratio (with / without) measured in the same run. Cases:
#   default        the built-in default scene as shipped (10 s, a row every step)
#   default-steps  the same for 600 s with a row every 144000 steps: stepping, not writing
#   free           lessons/intermediate_axis as shipped (12 s, one torque-free book, a row a step)
#   free-steps     the same for 5000 s with a row every 1200000 steps
#   rain           sphere_rain for 1 s (1000 spheres in contact), a row every 240 steps
#   startup        the default scene for one frame: loading and starting, subtracted from the
#                  others' CPU time for the last column (the stepping's own ratio)
# Appends one row per run to bench/results/<machine>/error_estimate.csv:
#   case,estimate,rep,wall_s,cpu_s,load1
# and prints the medians and ratios.
#   scripts/bench-error-estimate.sh [machine] [reps]     (default: uname -n, 5)
set -euo pipefail
cd "$(dirname "$0")/.."
machine="${1:-$(uname -n)}"
reps="${2:-5}"
cmake --build build/release --target tumble >&2
T=build/release/app/tumble
out="bench/results/$machine"
mkdir -p "$out"
csv="$out/error_estimate.csv"
[ -f "$csv" ] || echo "case,estimate,rep,wall_s,cpu_s,load1" > "$csv"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
declare -A args=(
  [default]="default"
  [default-steps]="default --duration 600 --every 144000"
  [free]="lessons/intermediate_axis"
  [free-steps]="lessons/intermediate_axis --duration 5000 --every 1200000"
  [rain]="sphere_rain --duration 1 --every 240"
  [startup]="default --duration 0.0167"
)
cases=(default default-steps free free-steps rain startup)
for rep in $(seq 1 "$reps"); do
  for c in "${cases[@]}"; do
    for estimate in off on; do
      flag=""
      [ "$estimate" = on ] && flag="--error-estimate"
      # shellcheck disable=SC2086
      /usr/bin/time -o "$work/t" -f "%e %U %S" "$T" simulate ${args[$c]} $flag -q -o "$work/x.csv"
      read -r wall user sys < "$work/t"
      load=$(cut -d' ' -f1 /proc/loadavg)
      echo "$c,$estimate,$rep,$wall,$(echo "$user + $sys" | bc),$load" >> "$csv"
    done
  done
done
# Medians of this run's rows (the last reps x cases x 2 of the file) and the ratios.
tail -n $((reps * ${#cases[@]} * 2)) "$csv" > "$work/run.csv"
python3 - "$work/run.csv" <<'EOF'
import statistics as st
import sys

rows = [line.strip().split(",") for line in open(sys.argv[1]) if line.strip()]


def median(case, estimate, column):
    return st.median(float(x[column]) for x in rows if x[0] == case and x[1] == estimate)


start = median("startup", "off", 4)
print("startup: %.3f s CPU" % start)
print("case           cpu off  cpu on  ratio  | wall off  wall on  ratio  | net ratio | load")
for case in ["default", "default-steps", "free", "free-steps", "rain"]:
    off, on = median(case, "off", 4), median(case, "on", 4)
    woff, won = median(case, "off", 3), median(case, "on", 3)
    loads = [float(x[5]) for x in rows if x[0] == case]
    print("%-14s %7.2f %7.2f %6.2f  | %8.2f %8.2f %6.2f  | %9.2f | %.1f-%.1f" % (
        case, off, on, on / off, woff, won, won / woff, (on - start) / (off - start),
        min(loads), max(loads)))
EOF
