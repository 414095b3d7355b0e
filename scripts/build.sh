#!/usr/bin/env bash
# Configures and builds the project in ./build (Release).
# Usage: scripts/build.sh [TARGET...]   (no target: everything, tests and experiments included)
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > build-configure.log 2>&1 || {
  cat build-configure.log
  exit 1
}
if [ $# -eq 0 ]; then
  cmake --build build -j"$(nproc)"
else
  cmake --build build -j"$(nproc)" --target "$@"
fi
