#!/usr/bin/env bash
# Regenerates every experiment and experiments/REPORT.md from the current code.
#   experiments/run_all.sh           full studies (about 20 min on 2 cores), results in
#                                    experiments/<study>/results/ and experiments/REPORT.md
#   experiments/run_all.sh --quick   reduced studies (under a minute), results and REPORT.md in
#                                    build-exp/experiments-quick/ (the committed results stay)
# Builds what it needs in build-exp/ (override with BUILD_DIR=...). Runs are single-threaded and
# sequential so that wall times are comparable.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(dirname "$here")"
build="${BUILD_DIR:-$repo/build-exp}"
quick=()
root="$here"
if [[ "${1:-}" == "--quick" ]]; then
  quick=(--quick)
  root="$build/experiments-quick"
fi
export OMP_NUM_THREADS=1
cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=Release -DVS_BUILD_BENCHMARKS=ON >/dev/null
cmake --build "$build" -j2 --target performance_benchmark work_precision stability esaform_cup step_stability \
  shell3d_benchmark calibration_cost make_report
bin="$build/experiments"
"$bin/performance_benchmark" "${quick[@]}" --out "$root/01_performance/results"
"$bin/work_precision" "${quick[@]}" --out "$root/02_work_precision/results"
"$bin/stability" "${quick[@]}" --out "$root/03_stability/results"
"$bin/esaform_cup" "${quick[@]}" --out "$root/04_esaform_cup/results"
"$bin/shell3d_benchmark" "${quick[@]}" --out "$root/05_shell3d/results"
"$bin/step_stability" "${quick[@]}" --out "$root/06_step_stability/results"
"$bin/calibration_cost" "${quick[@]}" --out "$root/07_calibration_cost/results"
"$bin/make_report" "${quick[@]}" --root "$root"
