#!/bin/sh
# The stills of docs/images/ that show what the teaching pictures look like at 640x360 (a size
# people use for slides and docs): lesson 4's Poinsot construction, lesson 1's wobbling plate and
# README's comparison of integrators, each as the lesson or README draws it.
#   scripts/teaching-stills.sh TUMBLE OUTDIR SUFFIX [OLD]
# OLD (any value): the commands as they were before issue 30 (README compared the integrators on
# the default scene with an energy chart), for the "before" stills of a build of that time.
set -eu
T=$1 out=$2 suffix=$3 old=${4:-}
mkdir -p "$out"
size="--width 640 --height 360 -q"
"$T" render lessons/intermediate_axis --poinsot book --vectors --chart w_body --chart-body book \
  $size --time 6 -o "$out/lesson4-$suffix.png"
"$T" render lessons/wobbling_plate --vectors --axes --trail-axis z --chart w_body,L \
  --chart-body plate $size --time 4.5 -o "$out/lesson1-$suffix.png"
if [ -n "$old" ]; then
  "$T" render default --compare euler,symplectic_euler,rk4,splitting --chart energy \
    $size --time 6 -o "$out/compare-$suffix.png"
else
  "$T" render lessons/intermediate_axis --compare euler,symplectic_euler,rk4,splitting \
    --chart energy_drift $size --time 6 -o "$out/compare-$suffix.png"
fi
