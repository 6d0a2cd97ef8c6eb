#!/usr/bin/env bash
# README command 1: install what is missing, build Release, render the built-in default scene.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --demo release tumble
mkdir -p out
build/release/app/tumble render -o out/default.mp4 "$@"
