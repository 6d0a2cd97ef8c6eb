#!/usr/bin/env bash
# Regenerates the committed state reference of the default scene on purpose, after a deliberate
# change to the physics or to the default scene. Review the diff before committing it.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh release
build/release/app/tumble simulate --quiet --duration 1 --every 24 -o tests/data/default_states.csv
rm -f tests/data/default_states.diagnostics.csv
git --no-pager diff --stat -- tests/data/default_states.csv
