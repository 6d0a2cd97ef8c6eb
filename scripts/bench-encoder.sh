#!/usr/bin/env bash
# Quality against bitrate of Tumble's H.264 output (issue 14: pick the default encoder settings by
# measurement). For each scene: the frames as lossless PNGs (the reference), then the same frames
# through `tumble render` at each CRF and preset; the decoded video is compared with the PNGs in
# RGB (gbrp, so that lost chroma counts: the yuv420p subsampling is part of what is measured) by
# PSNR and SSIM with FFmpeg's filters. Appends rows to bench/results/<machine>/encoder.csv:
#   scene,seconds,width,height,crf,preset,kbit_s,psnr_rgb_db,ssim_rgb,render_s
#   scripts/bench-encoder.sh [machine] [seconds]     (default: uname -n, 2 s of each scene)
set -euo pipefail
cd "$(dirname "$0")/.."
machine="${1:-$(uname -n)}"
seconds="${2:-2}"
cmake --build build/release --target tumble >&2
T=build/release/app/tumble
out="bench/results/$machine"
mkdir -p "$out"
csv="$out/encoder.csv"
[ -f "$csv" ] || echo "scene,seconds,width,height,crf,preset,kbit_s,psnr_rgb_db,ssim_rgb,render_s" > "$csv"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
for scene in tossed_book default dominoes; do
  rm -rf "$work/ref"
  "$T" render "$scene" --duration "$seconds" -q -o "$work/ref/"
  size=$(ffprobe -v error -show_entries stream=width,height -of csv=p=0 "$work/ref/000000.png")
  width=${size%,*}; height=${size#*,}
  fps=$("$T" explain "$scene" | sed -n 's/.* \([0-9]*\) fps.*/\1/p' | head -1)
  for preset in veryfast medium; do
    for crf in 12 15 18 21 24; do
      start=$(date +%s.%N)
      "$T" render "$scene" --duration "$seconds" --crf "$crf" --preset "$preset" -q -o "$work/v.mp4"
      end=$(date +%s.%N)
      kbits=$(ffprobe -v error -show_entries format=bit_rate -of csv=p=0 "$work/v.mp4")
      metrics=$(ffmpeg -nostats -i "$work/v.mp4" -framerate "${fps:-60}" -i "$work/ref/%06d.png" \
        -lavfi "[0:v]format=gbrp[a];[1:v]format=gbrp[b];[a]split[a1][a2];[b]split[b1][b2];[a1][b1]psnr;[a2][b2]ssim" \
        -f null - 2>&1)
      psnr=$(echo "$metrics" | sed -n 's/.*PSNR.* average:\([0-9.inf]*\).*/\1/p' | tail -1)
      ssim=$(echo "$metrics" | sed -n 's/.*SSIM.* All:\([0-9.]*\).*/\1/p' | tail -1)
      echo "$scene,$seconds,$width,$height,$crf,$preset,$((kbits / 1000)),$psnr,$ssim,$(echo "$end - $start" | bc)" | tee -a "$csv"
    done
  done
done
