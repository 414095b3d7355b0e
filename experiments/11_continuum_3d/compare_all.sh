#!/bin/bash
# Compare every stored vshell run (results/vshell_*) with every CalculiX reference
# (results/ex4b_n*) and the references with each other: results/comparison.csv; thickness strains
# over 0 <= r0 <= 50 mm and over 10 <= r0 <= 50 mm (label suffix _r0min10: without the pole region).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=$here/results/comparison.csv
rm -f "$out"
refs=("$here"/results/ex4b_n*)
for ref in "${refs[@]}"; do
  [ -f "$ref/load_travel.csv" ] || continue
  for other in "$here"/results/vshell_n* "${refs[@]}"; do
    [ "$other" = "$ref" ] && continue
    for rmin in 0 10; do
      python3 "$here/compare.py" "$ref" "$other" --csv "$out" --r0-min-mm $rmin \
        --label "$(basename "$other")_vs_$(basename "$ref")" || true
    done
  done
done
