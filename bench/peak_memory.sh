#!/usr/bin/env bash
# Peak memory of large scenes (issue 12's memory bounds): writes a scene of N spheres on a grid
# (spaced so that none touch, no gravity: every body in the broad phase, no contact work), then
# runs `tumble simulate` for 0.05 s (12 steps), and prints the run's peak resident memory as
# tumble reports it (getrusage), with the scene file's size and the run's wall time.
#   bench/peak_memory.sh [tumble binary] [bodies...]     default: build/release/app/tumble 200000
set -euo pipefail
tumble="${1:-build/release/app/tumble}"
shift || true
counts=("$@")
[ ${#counts[@]} -eq 0 ] && counts=(200000)
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

write_scene() { # N FILE
    awk -v n="$1" 'BEGIN {
        side = int(n ^ (1 / 3)) + 1
        printf "{\"format_version\": 1, \"world\": {\"gravity\": [0, 0, 0], \"duration\": 0.05,"
        printf " \"sleeping\": false}, \"render\": {\"fps\": 60}, \"bodies\": [\n"
        for (i = 0; i < n; i++) {
            x = i % side; y = int(i / side) % side; z = int(i / (side * side))
            printf "%s{\"name\": \"s%d\", \"shape\": {\"type\": \"sphere\", \"radius\": 0.1},", (i ? ",\n" : ""), i
            printf " \"position\": [%d, %d, %d], \"velocity\": [0.01, 0, 0]}", x, y, z
        }
        printf "]}\n"
    }' > "$2"
}

peak_of() { sed -n 's/.*peak memory \([0-9.]*\) MiB.*/\1/p' | tail -1; }

# The first (smallest) count is the baseline of this run: the last column is what each body
# adds above it (libraries, buffers and the program itself are in the baseline).
printf "%-8s  %-10s  %-10s  %-8s  %s\n" bodies "scene MiB" "peak MiB" "wall s" "KiB per body above the first row"
base_n=""; base_peak=""
for n in "${counts[@]}"; do
    scene="$work/scene_$n.json"
    write_scene "$n" "$scene"
    size=$(awk -v b="$(stat -c %s "$scene")" 'BEGIN { printf "%.1f", b / 1048576 }')
    start=$(date +%s.%N)
    sim_peak=$("$tumble" simulate "$scene" -o - --diagnostics none --every 1000 2>&1 >/dev/null | peak_of)
    wall=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
    if [ -z "$base_n" ]; then base_n=$n; base_peak=$sim_peak; per="(baseline)"; else
        per=$(awk -v p="$sim_peak" -v b="$base_peak" -v n="$n" -v m="$base_n" \
            'BEGIN { printf "%.2f", (p - b) * 1024 / (n - m) }')
    fi
    printf "%-8s  %-10s  %-10s  %-8s  %s\n" "$n" "$size" "$sim_peak" "$wall" "$per"
done
