#!/usr/bin/env bash
# Rewrites the project's goldens on purpose (after a deliberate change to a scene, the physics or
# the renderer): runs the project's regression suite, tests/goldens/suite.json, with --update,
# which writes the golden of every failing check (and every missing one) from this run and lists
# them; passing goldens are left as they are. Refuses to replace images drawn by another GL
# renderer; pass --force to replace them anyway. Look at the new images (the report) before
# committing them.
#   scripts/update-goldens.sh                        every failing or missing golden
#   scripts/update-goldens.sh --filter NAME          only the checks (or scenes) matching NAME
#   scripts/update-goldens.sh --report out/goldens   also an HTML report of the run
# After adding a scene to assets/scenes: add its entry to tests/goldens/suite.json, then run this.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh release
build/release/app/tumble test tests/goldens/suite.json --update --jobs 2 "$@"
