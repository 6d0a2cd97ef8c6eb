#!/usr/bin/env bash
# Installs the Debian 12 packages Tumble needs (only those missing), then configures and builds
# one CMake preset. Idempotent: a second run installs nothing and rebuilds nothing that is current.
#   scripts/setup.sh [preset [target]]   preset: release (default), debug, asan; target: all
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
target="${2:-all}"

# Exact package list: build tools, libraries, test and benchmark frameworks, and ffprobe for tests.
packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libboost-math-dev
  libosmesa6-dev libglm-dev libstb-dev libpng-dev
  libavcodec-dev libavformat-dev libavutil-dev libswscale-dev
  # GIF output: one palette per video (palettegen, paletteuse), render/gif_sink.h
  libavfilter-dev
  nlohmann-json3-dev libcli11-dev
  # Mesh bodies read Wavefront OBJ files (app/scene/obj_mesh.h): a small, maintained parser instead of
  # a hand-written one; its CMake config is found with no download.
  libtinyobjloader-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  ffmpeg
  # `tumble study` draws its plots by running gnuplot on generated scripts (pngcairo terminal,
  # DejaVu fonts): a small, long-kept Debian package without X (docs/study.md says why).
  gnuplot-nox fonts-dejavu-core
  # Tests of `tumble test` as CI and people use its outputs: the HTML report opened in a real
  # browser (headless Chromium: screenshot and DOM), the JUnit file validated against the schema CI
  # tools read (xmllint), the JSON Schemas checked by a real validator (Python's jsonschema).
  chromium libxml2-utils python3-jsonschema
  # The cluster test starts a real single-node Slurm (tests/cluster/slurm_test.sh, docs/cluster.md):
  # Debian's slurm-wlm (slurmctld, slurmd, sbatch) and munge, its authentication daemon. Only the
  # test runs them, each stopped by its process id when it ends.
  slurm-wlm munge
)

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

if [ ! -f "build/$preset/build.ninja" ]; then
  cmake --preset "$preset" >&2
fi
cmake --build --preset "$preset" --target "$target" >&2
