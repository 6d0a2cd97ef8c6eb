#!/bin/bash
# A real single-node Slurm on this machine, running the shipped scripts with the shipped package:
#   1. the binary from tumble_<version>_amd64.deb, extracted with `dpkg -x`;
#   2. munged, slurmctld and slurmd started here, as root, with everything (key, socket, state,
#      spool, logs, configuration) under the work folder and ports nobody listens on;
#   3. scripts/slurm/submit.sh: a checkpoints job, an array job of 4 shards starting from the
#      checkpoints, and the dependent join;
#   4. the joined video's decoded frames (ffmpeg, an independent decoder) compared with those of
#      a single-process render by the same binary, frame by frame;
#   5. the sweep array job (scripts/slurm/render-sweep.sbatch) over a two-scene sweep;
#   6. every daemon started here stopped by its process id, and checked gone.
# Any step that fails fails the test with the reason and the daemons' logs: Slurm not starting
# is a failure, never a skip.
# usage: slurm_test.sh PACKAGE_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
package_dir=$1 source_dir=$2 work=$3
timeout_s=${SLURM_TEST_TIMEOUT:-300}

fail() {
  echo "FAIL: $*" >&2
  exit 1
}
[ "$(id -u)" -eq 0 ] || fail "the Slurm test starts munged, slurmctld and slurmd as root; run it as root"
for tool in dpkg munged mungekey slurmctld slurmd sbatch scontrol sinfo ffmpeg ss; do
  command -v "$tool" > /dev/null || fail "$tool is not installed (scripts/setup.sh installs slurm-wlm and munge)"
done

rm -rf "$work"
mkdir -p "$work"/{pkg,munge,state,spool,log,run}
chmod 700 "$work" "$work/munge"

# 1. The package.
debs=("$package_dir"/tumble_*_amd64.deb)
{ [ ${#debs[@]} -eq 1 ] && [ -f "${debs[0]}" ]; } || fail "expected one tumble_*_amd64.deb in $package_dir, found: ${debs[*]}"
dpkg -x "${debs[0]}" "$work/pkg"
export TUMBLE=$work/pkg/usr/bin/tumble
[ -x "$TUMBLE" ] || fail "the package has no usr/bin/tumble"
echo "package: ${debs[0]} -> $TUMBLE ($("$TUMBLE" --version | sed -n 2p))"

# 2. The daemons, each in the foreground of its own background job, so that $! is its pid.
pids=()
stop_daemons() {
  local status=$?
  for pid in "${pids[@]}"; do kill "$pid" 2> /dev/null || true; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2> /dev/null || break; sleep 0.1; done
    if kill -0 "$pid" 2> /dev/null; then
      echo "daemon $pid did not stop on SIGTERM: SIGKILL" >&2
      kill -9 "$pid" 2> /dev/null || true
      status=1
    fi
  done
  if [ $status -ne 0 ]; then
    for f in "$work"/log/*.log "$work"/jobs/*.log; do
      [ -f "$f" ] && { echo "---- $f (last 30 lines)"; tail -n 30 "$f"; }
    done >&2
  fi
  exit $status
}
trap stop_daemons EXIT

free_port() {
  local port
  for _ in $(seq 100); do
    port=$((20000 + RANDOM % 20000))
    ss -ltn | awk '{print $4}' | grep -q ":$port\$" || { echo "$port"; return; }
  done
  fail "no free TCP port found"
}
wait_for() { # seconds, description, command...
  local seconds=$1 what=$2
  shift 2
  for _ in $(seq $((seconds * 5))); do "$@" > /dev/null 2>&1 && return 0; sleep 0.2; done
  fail "$what did not happen within $seconds s"
}

mkdir -p /run/munge # munged's default run folder; everything else of it is under $work
mungekey --create --keyfile="$work/munge/munge.key"
munged --foreground --force --key-file="$work/munge/munge.key" --socket="$work/munge/socket" \
  --pid-file="$work/munge/munged.pid" --log-file="$work/log/munged.log" \
  --seed-file="$work/munge/seed" > "$work/log/munged.out" 2>&1 &
pids+=($!)
wait_for 10 "munged creating its socket" test -S "$work/munge/socket"

host=$(hostname -s)
export SLURM_CONF=$work/slurm.conf
cat > "$SLURM_CONF" << EOF
ClusterName=tumbletest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$(free_port)
SlurmdPort=$(free_port)
AuthType=auth/munge
AuthInfo=socket=$work/munge/socket
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/run/slurmctld.pid
SlurmdPidFile=$work/run/slurmd.pid
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
ReturnToService=2
MinJobAge=600
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=tumble Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
slurmctld -D -f "$SLURM_CONF" > "$work/log/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" > "$work/log/slurmd.out" 2>&1 &
pids+=($!)
node_idle() { [ "$(sinfo -h -N -o %t 2> /dev/null)" = idle ]; }
wait_for 60 "the Slurm node becoming idle (slurmctld and slurmd up)" node_idle
echo "slurm: $(sinfo -h -N -o '%N %t %c CPUs')"

# 3. The shipped scripts: 4 shards of 8 s at 5 fps (40 frames, a key frame every 2 s: 0, 10, 20,
# 30), small frames so that the test stays short on 2 cores.
mkdir -p "$work/jobs"
cd "$work/jobs"
export EVERY=10 SHARD_OPTIONS="--fps 5 --duration 8" RENDER_OPTIONS="--width 160 --height 90"
jobs=$("$source_dir/scripts/slurm/submit.sh" default 4 "$work/out/default.mp4" "$work/checkpoints")
join_job=$(echo "$jobs" | tail -n 1)
echo "jobs: $(echo "$jobs" | tr '\n' ' ')"
deadline=$((SECONDS + timeout_s))
# Waits until every task of the jobs given is COMPLETED; fails on the first that failed, or on a
# job left waiting for one that did (DependencyNeverSatisfied), or at the deadline.
wait_jobs() {
  local job info pending
  while :; do
    pending=0
    for job in "$@"; do
      info=$(scontrol show job "$job" -o 2> /dev/null || true)
      if echo "$info" | grep -Eq 'JobState=(FAILED|CANCELLED|TIMEOUT|NODE_FAIL|OUT_OF_MEMORY)|Reason=DependencyNeverSatisfied'; then
        fail "job $job failed or waits for one that did: $(echo "$info" | grep -Eo '(JobId|JobState|Reason|ExitCode)=[^ ]*' | tr '\n' ' ')"
      fi
      echo "$info" | grep -Eq 'JobState=(PENDING|RUNNING|CONFIGURING|COMPLETING)' && pending=1
      [ -n "$info" ] || pending=1
    done
    [ $pending -eq 0 ] && return 0
    [ $SECONDS -lt $deadline ] || fail "jobs $* did not finish within $timeout_s s"
    sleep 1
  done
}
# shellcheck disable=SC2086 # the job ids, one word each
wait_jobs $jobs
echo "join job $join_job: COMPLETED after ${SECONDS} s"
grep -h "continuing from" tumble-shard-*.log | sed 's/^/  /'
[ "$(grep -l "continuing from" tumble-shard-*.log | wc -l)" -eq 3 ] ||
  fail "shards 1 to 3 should start from checkpoints (frames 10, 20, 30)"

# 4. A single-process render with the same binary, decoded frame by frame by ffmpeg.
"$TUMBLE" render default --fps 5 --duration 8 --width 160 --height 90 -q -o "$work/single.mp4"
frames() { ffmpeg -v error -i "$1" -f framemd5 - | grep -v '^#' | awk -F, '{print $2, $NF}'; }
frames "$work/out/default.mp4" > "$work/joined.md5"
frames "$work/single.mp4" > "$work/single.md5"
[ "$(wc -l < "$work/single.md5")" -eq 40 ] || fail "the single render decodes to $(wc -l < "$work/single.md5") frames, expected 40"
[ "$(sort -u -k2 "$work/single.md5" | wc -l)" -gt 30 ] || fail "the frames barely change: a weak comparison"
if ! diff "$work/single.md5" "$work/joined.md5" > "$work/frames.diff"; then
  fail "the joined video's frames differ from the single render's: $(head -n 6 "$work/frames.diff" | tr '\n' ' ')"
fi
echo "joined: 40 decoded frames equal the single render's"

# The sweep array job: two scenes from `tumble sweep`, one task each.
"$TUMBLE" sweep default --set world.integrator=euler,rk4 --set world.duration=1 -q -o "$work/sweep"
sweep_job=$(SWEEP=$work/sweep RENDER_OPTIONS="--fps 5 --width 160 --height 90" \
  sbatch --parsable --export=ALL --array=0-1 "$source_dir/scripts/slurm/render-sweep.sbatch")
wait_jobs "$sweep_job"
for i in 0 1; do
  video=$work/sweep/scene_00$i.mp4
  [ -f "$video" ] || fail "the sweep job wrote no $video"
  [ "$(frames "$video" | wc -l)" -eq 5 ] || fail "$video does not decode to 5 frames"
done
cmp -s <(frames "$work/sweep/scene_000.mp4") <(frames "$work/sweep/scene_001.mp4") &&
  fail "euler and rk4 gave the same frames: the sweep's scenes are not what they say"
echo "PASS: 40 decoded frames of the Slurm-joined video equal the single render's; the sweep array job rendered both scenes"
# 6. trap: stop_daemons
