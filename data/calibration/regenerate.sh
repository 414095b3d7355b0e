#!/bin/sh
# Regenerates the SYNTHETIC calibration data sets of this folder with the current forward solver
# (README.md, "Regenerating"). One command, from anywhere in the repository:
#
#   data/calibration/regenerate.sh [BUILD_DIR]
#
# BUILD_DIR (default: build) is configured if needed; only vs_system_tests is built. The files
# are written in place (VS_CALIBRATION_DATA_DIR=/some/dir writes them elsewhere). Afterwards
# CalibrationSystem.BundledSyntheticDataMatchTheCurrentSolver passes again.
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-"$root/build"}
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$build" -j2 --target vs_system_tests
"$build/tests/vs_system_tests" --gtest_also_run_disabled_tests \
  --gtest_filter=CalibrationSystem.DISABLED_WriteSyntheticDataSets
