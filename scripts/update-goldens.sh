#!/usr/bin/env bash
# Re-renders the committed golden images on purpose (after a deliberate change to a scene or to
# the renderer). Refuses when this machine's GL renderer differs from the one that made them;
# pass --force to replace them anyway. Review the images before committing them.
#   scripts/update-goldens.sh                  every golden
#   scripts/update-goldens.sh --add-missing    only add goldens for built-in scenes without any
#                                              (first, middle and last frame): after a new scene
#   scripts/update-goldens.sh --scene NAME     only that scene's goldens (repeatable)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh release
build/release/app/tumble goldens update tests/goldens/goldens.json "$@"
