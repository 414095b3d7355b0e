#!/usr/bin/env bash
# The newcomer's first command: installs what is missing, builds, and runs paper example 1
# (hemispherical punch stretching) into out/ex1_hemispherical_stretching with CSV curves and plots.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh vshell
./build/app/vshell run data/scenes/ex1_hemispherical_stretching.toml "$@"
