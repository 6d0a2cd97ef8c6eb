#!/usr/bin/env bash
# README command 2: install what is missing, build Release, run the whole test suite with CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh release
ctest --preset release "$@"
