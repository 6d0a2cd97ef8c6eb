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

demo_packages=(
  # The C++ compiler alone, not build-essential: nothing here runs make, and build-essential's
  # dpkg-dev brings Perl (about 7 s of the first command on a bare machine); the tests add dpkg-dev.
  g++ cmake ninja-build pkg-config
  libeigen3-dev
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
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "tumble setup: installing ${missing[*]}" >&2
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# The demo configures a new build folder without the tests and benchmarks (their frameworks are
# not installed); the full set-up turns them on, also in a folder the demo configured.
cache="build/$preset/CMakeCache.txt"
if [ $demo = 1 ]; then
  [ -f "build/$preset/build.ninja" ] ||
    cmake --preset "$preset" -DTUMBLE_BUILD_TESTS=OFF -DTUMBLE_BUILD_BENCH=OFF >&2
elif [ ! -f "build/$preset/build.ninja" ] || grep -q '^TUMBLE_BUILD_\(TESTS\|BENCH\):BOOL=OFF' "$cache"; then
  cmake --preset "$preset" -DTUMBLE_BUILD_TESTS=ON -DTUMBLE_BUILD_BENCH=ON >&2
fi
cmake --build --preset "$preset" --target "$target" >&2
