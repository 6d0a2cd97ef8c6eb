#!/usr/bin/env bash
# Times a clean Release build of the `tumble` executable, the way README's first command builds it
# (scripts/setup.sh --demo: tests and benchmarks off), with ccache off, one build at a time.
#   scripts/bench-build.sh [--reps=2] [--label=NAME] [--target=tumble] [--jobs=2] [--jobs-log=FILE] [-DVAR=VALUE...]
# Prints each run and the median, and appends them to bench/results/<machine>/build_times.csv
# (label, commit, run, seconds, load at start). The machine is shared: compare medians taken in one
# sitting, and say the load. --jobs-log=FILE keeps the last run's job times (start and end of each
# compile and link, ms, from ninja's .ninja_log), to see which jobs start late and leave a core idle.
# --jobs=N: parallel jobs (default 2, the 2-core machine's cores; --jobs=0 leaves ninja's default,
# cores + 2, which is what `cmake --build --preset` runs when the preset names none).
set -euo pipefail
cd "$(dirname "$0")/.."
reps=2
label="$(git rev-parse --short HEAD)"
target=tumble
jobs_log=""
jobs=2
defines=()
for arg in "$@"; do
  case "$arg" in
    --reps=*) reps="${arg#--reps=}" ;;
    --label=*) label="${arg#--label=}" ;;
    --target=*) target="${arg#--target=}" ;;
    --jobs-log=*) jobs_log="${arg#--jobs-log=}" ;;
    --jobs=*) jobs="${arg#--jobs=}" ;;
    -D*) defines+=("$arg") ;;
    *) echo "bench-build.sh: unknown option '$arg' (expected --reps=N, --label=NAME, --target=T, --jobs=N, --jobs-log=FILE, -DVAR=VALUE)" >&2
       exit 2 ;;
  esac
done
out="bench/results/$(uname -n)"
mkdir -p "$out"
csv="$out/build_times.csv"
[ -f "$csv" ] || echo "label,commit,target,run,seconds,load1_at_start" > "$csv"
scratch="$(mktemp -d /tmp/tumble-build-bench.XXXXXX)"
trap 'rm -rf "$scratch"' EXIT
times=()
jobs_arg=()
[ "$jobs" = 0 ] || jobs_arg=(-j "$jobs")
for run in $(seq 1 "$reps"); do
  rm -rf "$scratch/b"
  CCACHE_DISABLE=1 cmake -S . -B "$scratch/b" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DTUMBLE_BUILD_TESTS=OFF -DTUMBLE_BUILD_BENCH=OFF -DCMAKE_CXX_COMPILER_LAUNCHER= \
    "${defines[@]}" >/dev/null
  load="$(cut -d' ' -f1 /proc/loadavg)"
  start=$(date +%s.%N)
  if ! CCACHE_DISABLE=1 cmake --build "$scratch/b" --target "$target" "${jobs_arg[@]}" > "$scratch/build.log" 2>&1; then
    tail -30 "$scratch/build.log" >&2
    echo "bench-build.sh: the build failed (run $run)" >&2
    exit 1
  fi
  end=$(date +%s.%N)
  secs=$(awk -v a="$start" -v b="$end" 'BEGIN {printf "%.1f", b - a}')
  echo "run $run: ${secs} s (load at start $load)"
  echo "$label,$(git rev-parse --short HEAD),$target,$run,$secs,$load" >> "$csv"
  times+=("$secs")
  if [ -n "$jobs_log" ]; then cp "$scratch/b/.ninja_log" "$jobs_log"; fi
done
median=$(printf "%s\n" "${times[@]}" | sort -n | awk '{a[NR]=$1} END {print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}')
echo "median of $reps: ${median} s"
