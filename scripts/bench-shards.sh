#!/usr/bin/env bash
# Shards on one machine (issue 18, docs/cluster.md "Measured on this machine"), medians of
# `repeats` runs, appended to bench/results/<machine>/shards.csv:
#   - the 600-frame default demo (1280x720, x264 medium, CRF 18) as 1 shard (a plain render), and
#     as 2 and 4 shards: the checkpoint pass (tumble simulate --checkpoint-every 120), the shards
#     all at once (and 4 shards two at a time, as a 2-CPU Slurm node runs them), the join; each
#     joined video's decoded frames compared with the plain render's;
#   - the sphere-rain scene's stage costs for the paper estimate: the checkpoint pass per frame,
#     and a 60-frame 1920x1080 shard continued from a checkpoint, per frame.
# And to bench/results/<machine>/keyframes.csv, what a key frame every two seconds (with the
# encoder starting afresh) costs: the demo's lossless frames encoded by ffmpeg's libx264 with the same
# settings as pieces of 1, 2, 5 and 10 s (the whole demo), and Tumble's own video, each compared
# with the lossless frames (PSNR in RGB, as scripts/bench-encoder.sh).
#   scripts/bench-shards.sh [machine] [repeats]     (default: uname -n, 3)
set -euo pipefail
cd "$(dirname "$0")/.."
machine="${1:-$(uname -n)}"
repeats="${2:-3}"
cmake --build build/release --target tumble >&2
T=$PWD/build/release/app/tumble
out="$PWD/bench/results/$machine"
mkdir -p "$out"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"

now() { date +%s.%N; }
since() { echo "$(now) - $1" | bc; }
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
frames() { ffmpeg -v error -i "$1" -f framemd5 - | grep -v '^#'; }

# One run of N shards at `jobs` at a time; prints "checkpoint shards join".
run_shards() {
  local n=$1 jobs=$2 t
  rm -rf ck parts && mkdir parts
  t=$(now)
  "$T" simulate default --checkpoint-every 120 --checkpoints ck -q
  local ck_s; ck_s=$(since "$t")
  t=$(now)
  # shellcheck disable=SC2016 # $0 is expanded by the inner shell: each line, run as written
  "$T" shards default --count "$n" -o parts/demo.mp4 --from-checkpoints ck --tumble "$T" -q |
    xargs -d '\n' -n 1 -P "$jobs" sh -c 'eval "$0 -q"'
  local shards_s; shards_s=$(since "$t")
  t=$(now)
  eval "$("$T" shards default --count "$n" -o parts/demo.mp4 --tumble "$T" -q --join) -q"
  echo "$ck_s $shards_s $(since "$t")"
}

csv="$out/shards.csv"
[ -f "$csv" ] || echo "date,machine,load_1min,case,shards,at_once,repeats,checkpoint_s,shards_s,join_s,total_s,speedup,frames_identical" > "$csv"
stamp=$(date -u +%FT%T)
load() { cut -d' ' -f1 /proc/loadavg; }
declare -a one=()
for _ in $(seq "$repeats"); do
  t=$(now)
  "$T" render default -q -o one.mp4
  one+=("$(since "$t")")
done
one_s=$(printf '%s\n' "${one[@]}" | median)
frames one.mp4 > one.md5
echo "$stamp,$machine,$(load),demo-600,1,1,$repeats,0,$one_s,0,$one_s,1.00,yes" | tee -a "$csv"
for case in "2 2" "4 4" "4 2"; do
  # shellcheck disable=SC2086 # "shards at_once": two words on purpose
  set -- $case
  ck=() sh=() jn=() total=()
  for _ in $(seq "$repeats"); do
    read -r a b c <<< "$(run_shards "$1" "$2")"
    ck+=("$a") sh+=("$b") jn+=("$c") total+=("$(echo "$a + $b + $c" | bc)")
  done
  same=$(frames parts/demo.mp4 | cmp -s - one.md5 && echo yes || echo no)
  t_total=$(printf '%s\n' "${total[@]}" | median)
  echo "$stamp,$machine,$(load),demo-600,$1,$2,$repeats,$(printf '%s\n' "${ck[@]}" | median),$(printf '%s\n' "${sh[@]}" | median),$(printf '%s\n' "${jn[@]}" | median),$t_total,$(echo "scale=2; $one_s / $t_total" | bc),$same" | tee -a "$csv"
done

# Sphere rain (1000 spheres), the paper estimate's stage costs, per frame.
rm -rf ck
t=$(now)
"$T" simulate sphere_rain --checkpoint-every 60 --checkpoints ck -q
rain_frames=$("$T" explain sphere_rain | sed -n 's/.* \([0-9]*\) frames at.*/\1/p' | head -1)
physics_ms=$(echo "scale=3; 1000 * $(since "$t") / $rain_frames" | bc)
t=$(now)
"$T" render sphere_rain --width 1920 --height 1080 --frames 240:300 --from-checkpoints ck -q -o rain.mp4
render_ms=$(echo "scale=1; 1000 * $(since "$t") / 60" | bc)
echo "$stamp,$machine,$(load),rain-physics-ms-per-frame,,,1,$physics_ms,,,,," | tee -a "$csv"
echo "$stamp,$machine,$(load),rain-1080p-shard-ms-per-frame,,,1,,$render_ms,,,," | tee -a "$csv"

# What the key frames cost.
kcsv="$out/keyframes.csv"
[ -f "$kcsv" ] || echo "date,machine,video,kbit_s,psnr_rgb_db" > "$kcsv"
"$T" render default -q -o ref/
psnr() {
  ffmpeg -nostats -i "$1" -framerate 60 -i ref/%06d.png \
    -lavfi "[0:v]format=gbrp[a];[1:v]format=gbrp[b];[a][b]psnr" -f null - 2>&1 |
    sed -n 's/.*PSNR.* average:\([0-9.inf]*\).*/\1/p' | tail -1
}
kbits() { echo $(($(ffprobe -v error -show_entries format=bit_rate -of csv=p=0 "$1") / 1000)); }
x264=(-c:v libx264 -preset medium -crf 18 -threads 1 -x264-params cpu-independent=1
  -vf scale=out_color_matrix=bt709:out_range=tv -pix_fmt yuv420p -color_range tv
  -colorspace bt709 -color_primaries bt709 -color_trc bt709)
# The same frames as pieces of 1, 2, 5 and 10 s, each piece a fresh encode, joined by a remux.
for seconds in 1 2 5 10; do
  : > pieces.txt
  for s in $(seq 0 $((10 / seconds - 1))); do
    ffmpeg -v error -y -framerate 60 -start_number $((60 * seconds * s)) -i ref/%06d.png \
      -frames:v $((60 * seconds)) "${x264[@]}" "piece$s.mp4"
    echo "file 'piece$s.mp4'" >> pieces.txt
  done
  ffmpeg -v error -y -f concat -safe 0 -i pieces.txt -c copy "pieces_$seconds.mp4"
  echo "$stamp,$machine,ffmpeg restarted every ${seconds} s,$(kbits "pieces_$seconds.mp4"),$(psnr "pieces_$seconds.mp4")" | tee -a "$kcsv"
done
echo "$stamp,$machine,tumble render (restarted every 2 s),$(kbits one.mp4),$(psnr one.mp4)" | tee -a "$kcsv"
