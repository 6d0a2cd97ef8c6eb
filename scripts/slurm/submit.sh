#!/bin/bash
# Submits a whole Tumble render to Slurm (docs/cluster.md, step by step):
#   [checkpoints job] -> array job of N shards -> join job, each waiting for the one before.
# usage: scripts/slurm/submit.sh SCENE N OUT [CHECKPOINT_DIR]
#   SCENE  scene file or built-in name;  N  number of shards;  OUT  the joined video (.mp4)
#   CHECKPOINT_DIR  optional: step the scene once first, writing checkpoints there (every EVERY
#                   frames, default 120), and start every shard from the nearest one
# Environment passed on: TUMBLE, SHARD_OPTIONS, RENDER_OPTIONS, EVERY (see the .sbatch files);
# SBATCH_OPTIONS: options for every sbatch call (e.g. "--partition=render --cpus-per-task=8").
# Prints the job ids, one per line; the last is the join's.
set -euo pipefail
[ $# -ge 3 ] || { sed -n '2,12p' "$0" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
export SCENE=$1 SHARDS=$2 OUT=$3 CHECKPOINTS=${4:-}
# shellcheck disable=SC2206
sbatch_options=(${SBATCH_OPTIONS:-})
after=()
if [ -n "$CHECKPOINTS" ]; then
  ck=$(sbatch --parsable --export=ALL "${sbatch_options[@]}" "$here/checkpoints.sbatch")
  echo "$ck"
  after=(--dependency=afterok:"$ck")
fi
shards=$(sbatch --parsable --export=ALL --array=0-$((SHARDS - 1)) "${after[@]}" \
  "${sbatch_options[@]}" "$here/render-shards.sbatch")
echo "$shards"
sbatch --parsable --export=ALL --dependency=afterok:"$shards" "${sbatch_options[@]}" \
  "$here/join.sbatch"
