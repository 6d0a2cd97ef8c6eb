#!/usr/bin/env bash
# scripts/setup.sh builds the physics core (TUMBLE_WITH_RENDER=OFF) while apt installs the rest,
# then configures the same folder with everything and builds `tumble`. That saves time only if the
# full configuration keeps the core's compile commands (ninja rebuilds an object whose command
# changed) and if the core configuration needs nothing beyond the compiler, CMake and Eigen.
#   core_first_test.sh SOURCE_DIR SCRATCH_DIR
set -euo pipefail
src="$1"
dir="$2/core-first"
rm -rf "$dir"
mkdir -p "$dir"
core_targets=(tumble_physics tumble_exact tumble_scenes tumble_io)

cmake -S "$src" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DTUMBLE_WITH_APP=OFF \
  -DTUMBLE_WITH_RENDER=OFF -DTUMBLE_BUILD_TESTS=OFF -DTUMBLE_BUILD_BENCH=OFF >/dev/null
# The core configuration looks for no package of render/ or app/.
if grep -q '^\(OSMESA\|LIBAV\|PNG\|STB\)_FOUND' "$dir/CMakeCache.txt"; then
  echo "FAIL: the core configuration looked for render's packages" >&2
  exit 1
fi
(cd "$dir" && ninja -t targets all) > "$dir/core-targets.txt"
for t in tumble_render tumble_scene tumble; do
  if grep -q "^$t:" "$dir/core-targets.txt"; then
    echo "FAIL: the core configuration has target $t" >&2
    exit 1
  fi
done
(cd "$dir" && ninja -t commands "${core_targets[@]}") > "$dir/core.txt"
[ "$(grep -c ' -c ' "$dir/core.txt")" -ge 4 ] || { echo "FAIL: no compile commands for the core" >&2; exit 1; }

# As README command 2 configures it: tests and benchmarks on.
cmake -S "$src" -B "$dir" -DTUMBLE_WITH_APP=ON -DTUMBLE_WITH_RENDER=ON -DTUMBLE_BUILD_TESTS=ON \
  -DTUMBLE_BUILD_BENCH=ON >/dev/null
# To a file, then grep: `ninja ... | grep -q` under pipefail failed whenever grep had found the
# target and exited before ninja finished writing (SIGPIPE): two suite runs in two on 2026-11-28.
(cd "$dir" && ninja -t targets all) > "$dir/full-targets.txt"
grep -q '^tumble:' "$dir/full-targets.txt" || { echo "FAIL: no tumble target" >&2; exit 1; }
(cd "$dir" && ninja -t commands "${core_targets[@]}") > "$dir/full.txt"
if ! diff "$dir/core.txt" "$dir/full.txt" >&2; then
  echo "FAIL: the full configuration changes the core's compile commands (above): the core built" \
       "while apt installs would be compiled again" >&2
  exit 1
fi
echo "the core's $(grep -c ' -c ' "$dir/core.txt") compile commands are the same in both configurations"
rm -rf "$dir"
