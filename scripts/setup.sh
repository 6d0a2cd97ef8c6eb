#!/usr/bin/env bash
# Installs the Debian 12 packages Tumble needs (only those missing), then configures and builds
# one CMake preset. Idempotent: a second run installs nothing and rebuilds nothing that is current.
#   scripts/setup.sh [--demo] [preset [target]]   preset: release (default), debug, asan; target: all
#   scripts/setup.sh --list demo|test             the packages of one group, one per line
# Two groups: `demo` is what building and running `tumble` needs (README command 1, scripts/demo.sh,
# passes --demo and configures without the tests and benchmarks); `test` is what the test suite,
# the benchmarks, the packaging and the scripts add (README command 2, scripts/test.sh: both
# groups). tests/setup/external_programs.py checks that every program the tests, scripts and CPack
# run comes from a package here (or from one every Debian machine has).
set -euo pipefail
cd "$(dirname "$0")/.."

# What the physics core builds with (TUMBLE_WITH_RENDER=OFF): installed first on a new machine, so
# that the core compiles while apt installs the rest (see below).
core_packages=(
  # The C++ compiler alone, not build-essential: nothing here runs make, and build-essential's
  # dpkg-dev brings Perl (about 7 s of the first command on a bare machine); the tests add dpkg-dev.
  g++ cmake ninja-build pkg-config
  libeigen3-dev
)
demo_packages=(
  "${core_packages[@]}"
  libosmesa6-dev libglm-dev libstb-dev libpng-dev
  libavcodec-dev libavformat-dev libavutil-dev libswscale-dev
  # GIF output: one palette per video (palettegen, paletteuse), render/gif_sink.h
  libavfilter-dev
  nlohmann-json3-dev libcli11-dev
  # Mesh bodies read Wavefront OBJ files (app/scene/obj_mesh.h): a small, maintained parser instead of
  # a hand-written one; its CMake config is found with no download.
  libtinyobjloader-dev
)
test_packages=(
  # Test and benchmark frameworks; Boost.Math is the independent reference of physics' elliptic
  # functions (tests/physics/elliptic_test.cpp), never linked into tumble.
  libgtest-dev libgmock-dev libbenchmark-dev libboost-math-dev
  # The peer benchmark (bench/peers, scripts/bench-peers.sh): the same scenes in ODE, measured side
  # by side with Tumble. A benchmark only, never linked into `tumble`; the build skips it without.
  libode-dev
  # ffmpeg and ffprobe: an independent decoder of the videos the tests check.
  ffmpeg
  # `tumble study` and `tumble plot` draw by running gnuplot on generated scripts (pngcairo
  # terminal, DejaVu fonts): a small, long-kept Debian package without X (docs/study.md says why).
  # The .deb recommends them; the demo does not need them.
  gnuplot-nox fonts-dejavu-core
  # Tests of `tumble test` as CI and people use its outputs: the HTML report opened in a real
  # browser (headless Chromium: screenshot and DOM), the JUnit file validated against the schema CI
  # tools read (xmllint), the JSON Schemas checked by a real validator (Python's jsonschema).
  chromium libxml2-utils python3-jsonschema
  # The cluster test starts a real single-node Slurm (tests/app/cluster/slurm_test.sh,
  # docs/cluster.md): Debian's slurm-wlm (slurmctld, slurmd, sbatch) and munge, its authentication
  # daemon, with a free port found by `ss` (iproute2). Only the test runs them, each stopped by its
  # process id.
  slurm-wlm munge iproute2
  # CPack's DEB generator (Package.BuildsTheDeb) runs `file` to find the binaries whose libraries
  # dpkg-shlibdeps (dpkg-dev) names in Depends.
  file dpkg-dev
  # The benchmark scripts time whole commands (/usr/bin/time) and do their arithmetic with bc.
  time bc
  # The Python module `tumble` (app/python, README "From Python", docs/python.md): bound with
  # pybind11 for Debian's /usr/bin/python3 (its headers in python3-dev), arrays from NumPy. The
  # build makes it when these are installed; the demo does without.
  pybind11-dev python3-dev python3-numpy
  # Its tests (tests/python: pytest) and notebooks (examples/notebooks), executed in CTest by
  # nbclient on an IPython kernel, their plots drawn by matplotlib.
  python3-pytest python3-matplotlib python3-nbclient python3-nbformat python3-ipykernel
)

if [ "${1:-}" = "--list" ]; then
  case "${2:-}" in
    demo) printf '%s\n' "${demo_packages[@]}" ;;
    test) printf '%s\n' "${test_packages[@]}" ;;
    *) echo "usage: scripts/setup.sh --list demo|test" >&2; exit 2 ;;
  esac
  exit 0
fi
demo=0
if [ "${1:-}" = "--demo" ]; then
  demo=1
  shift
fi
preset="${1:-release}"
target="${2:-all}"

packages=("${demo_packages[@]}")
[ $demo = 1 ] || packages+=("${test_packages[@]}")
missing_of() {
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || echo "$p"
  done
}
mapfile -t missing < <(missing_of "${packages[@]}")
mapfile -t missing_core < <(missing_of "${core_packages[@]}")
sudo_cmd=()
[ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
install() {
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "$@"
}

# On a new machine (packages beyond the core missing, no build folder yet) the physics core is
# built while apt installs the rest: it needs only the compiler, CMake and Eigen, and its compile
# commands are the same in the full configuration below, which therefore reuses its objects. On a
# bare Debian 12 root that takes the core's ~28 s of compiling off README command 1's critical
# path (docs/engineering.md). The build runs in its own process group, stopped with this script
# (Ctrl-C, an apt failure): a script's background job would otherwise ignore Ctrl-C.
early=""
stop_early() { if [ -n "$early" ]; then kill -TERM -- "-$early" 2>/dev/null || true; fi; }
trap stop_early EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
build_dir="build/$preset"
if [ ${#missing[@]} -gt 0 ]; then
  echo "tumble setup: installing ${missing[*]}" >&2
  "${sudo_cmd[@]}" apt-get update -qq
  if [ ${#missing[@]} -gt ${#missing_core[@]} ] && [ ! -f "$build_dir/build.ninja" ]; then
    [ ${#missing_core[@]} -eq 0 ] || install "${missing_core[@]}"
    cmake --preset "$preset" -DTUMBLE_WITH_APP=OFF -DTUMBLE_WITH_RENDER=OFF \
      -DTUMBLE_BUILD_TESTS=OFF -DTUMBLE_BUILD_BENCH=OFF >&2
    # On every core: one compile job instead of two did not shorten the install beside it (62
    # against 64 s on a bare root, 2 cores; about 46 s with no compiler beside it).
    echo "tumble setup: building the physics core while the rest installs" >&2
    setsid cmake --build --preset "$preset" >&2 &
    early=$!
    mapfile -t missing < <(missing_of "${packages[@]}")
    install "${missing[@]}"
    core_status=0
    wait "$early" || core_status=$?
    early=""
    if [ $core_status -ne 0 ]; then
      echo "tumble setup: building the physics core failed (exit $core_status; its errors are above)" >&2
      exit 1
    fi
  else
    install "${missing[@]}"
  fi
fi

# The demo configures a new build folder without the tests and benchmarks (their frameworks are
# not installed); the full set-up turns them on, also in a folder the demo configured. A folder of
# the core alone (above) is configured again with everything.
cache="$build_dir/CMakeCache.txt"
configure=()
if [ ! -f "$build_dir/build.ninja" ] || grep -q '^TUMBLE_WITH_\(APP\|RENDER\):BOOL=OFF' "$cache"; then
  configure=(-DTUMBLE_WITH_APP=ON -DTUMBLE_WITH_RENDER=ON)
  if [ $demo = 1 ]; then
    configure+=(-DTUMBLE_BUILD_TESTS=OFF -DTUMBLE_BUILD_BENCH=OFF)
  else
    configure+=(-DTUMBLE_BUILD_TESTS=ON -DTUMBLE_BUILD_BENCH=ON)
  fi
elif [ $demo = 0 ] && grep -q '^TUMBLE_BUILD_\(TESTS\|BENCH\):BOOL=OFF' "$cache"; then
  configure=(-DTUMBLE_BUILD_TESTS=ON -DTUMBLE_BUILD_BENCH=ON)
fi
[ ${#configure[@]} -eq 0 ] || cmake --preset "$preset" "${configure[@]}" >&2
cmake --build --preset "$preset" --target "$target" >&2
