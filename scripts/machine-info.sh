#!/usr/bin/env bash
# What the machine is, when, and its load: the header every benchmark script keeps beside its
# results (bench/results/<machine>/*_cpu.txt), since the machines are shared and their speed moves
# (bench/README.md). Extra lines given as arguments are printed before the date.
#   scripts/machine-info.sh ["ode: 0.16.2" ...] > FILE
set -euo pipefail
grep -m1 "model name" /proc/cpuinfo
grep -m1 "cpu MHz" /proc/cpuinfo
grep -m1 "cache size" /proc/cpuinfo
echo "logical cpus: $(nproc)"
uname -srm
for line in "$@"; do echo "$line"; done
date -u +"measured: %Y-%m-%d %H:%M UTC"
echo "load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
