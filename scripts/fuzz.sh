#!/usr/bin/env bash
# Fuzzes the libFuzzer harnesses of tests/fuzz (README there) with ASan + UBSan, clang's libFuzzer.
#   scripts/fuzz.sh [seconds-per-harness] [harness...]   fuzz each (default 60 s; all three)
#   scripts/fuzz.sh --merge [harness...]                 fold what fuzzing found into the corpus
# Harnesses: scene_loader, obj_reader, suite_loader. Installs clang and its runtimes if missing
# (as scripts/setup.sh installs the rest: run that first), configures and builds the `fuzz` preset.
# Each harness grows a scratch corpus, build/fuzz/corpus/<harness>, seeded from the committed one,
# tests/fuzz/corpus/<harness>, which fuzzing never writes. It runs in fork mode, going on after a
# crash (libFuzzer keeps one input per distinct stack); new crash-/leak-/oom-/timeout- inputs are
# copied to tests/fuzz/crashers/<harness>/, which the test suite replays (commit them, with the
# fix). Logs: build/fuzz/logs/<harness>.log. One summary line per harness: executions, coverage
# (cov: edges, ft: features, from libFuzzer's last status line) and crashes found.
# --merge adds to tests/fuzz/corpus/<harness> only the scratch inputs that reach new features
# (libFuzzer -merge=1), and only if that stays under 100 files and 200 KB; else it adds nothing.
set -euo pipefail
cd "$(dirname "$0")/.."

all_harnesses=(scene_loader obj_reader suite_loader)
build=build/fuzz

# Bytes an input may grow to: a scene or a mesh of 64 KB, a suite of 16 KB.
max_len() { [ "$1" = suite_loader ] && echo 16384 || echo 65536; }
dict() {
  case "$1" in
    scene_loader) echo tests/fuzz/scene.dict ;;
    obj_reader) echo tests/fuzz/obj.dict ;;
    suite_loader) echo tests/fuzz/suite.dict ;;
  esac
}

install_clang() {
  local packages=(clang libclang-rt-dev) missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return
  echo "tumble fuzz: installing ${missing[*]}" >&2
  local sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends \
    "${missing[@]}"
}

build_fuzzers() {
  install_clang
  if [ ! -f "$build/build.ninja" ]; then
    cmake --preset fuzz >&2 || { echo "tumble fuzz: configure failed (libraries missing? run scripts/setup.sh)" >&2; exit 1; }
  fi
  cmake --build --preset fuzz >&2 # the preset's targets: the three fuzz_* executables
}

check_harness() {
  case " ${all_harnesses[*]} " in *" $1 "*) ;; *)
    echo "tumble fuzz: no harness '$1' (harnesses: ${all_harnesses[*]})" >&2; exit 2 ;;
  esac
}

# Fuzzes harness $1 for $2 seconds and prints its summary line.
fuzz_one() {
  local h=$1 seconds=$2
  local corpus=$build/corpus/$h artifacts=$build/artifacts/$h log=$build/logs/$h.log
  mkdir -p "$corpus" "$artifacts" "$build/logs" "tests/fuzz/crashers/$h"
  cp -n tests/fuzz/corpus/"$h"/* "$corpus"/
  ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1} UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1} \
    "$build/tests/fuzz/fuzz_$h" -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
    -max_total_time="$seconds" -dict="$(dict "$h")" -max_len="$(max_len "$h")" \
    -rss_limit_mb=2048 -timeout=10 -artifact_prefix="$artifacts/" "$corpus" >"$log" 2>&1 || true
  local found=0
  for a in "$artifacts"/crash-* "$artifacts"/leak-* "$artifacts"/oom-* "$artifacts"/timeout-*; do
    [ -e "$a" ] || continue
    if [ ! -e "tests/fuzz/crashers/$h/$(basename "$a")" ]; then
      cp "$a" "tests/fuzz/crashers/$h/"
      found=$((found + 1))
    fi
  done
  # Last status line, fork mode: "#123: cov: 1500 ft: 6000 corp: 300 exec/s 900 ... time: 60s".
  local last execs cov ft
  last=$(grep -E '^#[0-9]+:? .*cov: ' "$log" | tail -n 1 || true)
  execs=$(sed -E 's/^#([0-9]+).*/\1/' <<<"$last")
  cov=$(grep -oE 'cov: [0-9]+' <<<"$last" | cut -d' ' -f2 || true)
  ft=$(grep -oE 'ft: [0-9]+' <<<"$last" | cut -d' ' -f2 || true)
  printf '%-16s %4ss  execs %-9s cov %-6s ft %-7s new crashers %s%s\n' "$h" "$seconds" \
    "${execs:-?}" "${cov:-?}" "${ft:-?}" "$found" \
    "$([ "$found" -gt 0 ] && echo " (tests/fuzz/crashers/$h/, log $log)")"
}

# Adds the scratch corpus's new-feature inputs to tests/fuzz/corpus/$1, if they stay small. The
# merge runs on a copy, so the committed corpus gets all of them or none.
merge_one() {
  local h=$1 committed=tests/fuzz/corpus/$1 scratch=$build/corpus/$1 merged=$build/merge/$1
  [ -d "$scratch" ] || { echo "$h: no scratch corpus ($scratch): fuzz first" >&2; return; }
  rm -rf "$merged"
  mkdir -p "$merged"
  cp "$committed"/* "$merged"/
  "$build/tests/fuzz/fuzz_$h" -merge=1 -max_len="$(max_len "$h")" -rss_limit_mb=2048 \
    -timeout=10 "$merged" "$scratch" >"$build/logs/$h.merge.log" 2>&1
  local added count=0 bytes=0
  added=$(comm -13 <(ls "$committed" | sort) <(ls "$merged" | sort))
  for f in $added; do count=$((count + 1)); bytes=$((bytes + $(stat -c %s "$merged/$f"))); done
  if [ "$count" -gt 100 ] || [ "$bytes" -gt 204800 ]; then
    echo "$h: merge would add $count files, $bytes bytes: too many, added nothing"
  else
    for f in $added; do cp "$merged/$f" "$committed/"; done
    echo "$h: added $count files, $bytes bytes to $committed"
  fi
}

merge=0
if [ "${1:-}" = --merge ]; then
  merge=1
  shift
fi
seconds=60
if [ $merge -eq 0 ] && [[ "${1:-}" =~ ^[0-9]+$ ]]; then
  seconds=$1
  shift
fi
harnesses=("$@")
[ ${#harnesses[@]} -eq 0 ] && harnesses=("${all_harnesses[@]}")
for h in "${harnesses[@]}"; do check_harness "$h"; done

build_fuzzers
for h in "${harnesses[@]}"; do
  if [ $merge -eq 1 ]; then merge_one "$h"; else fuzz_one "$h" "$seconds"; fi
done
