#!/bin/bash
# Compare every stored vshell run (results/vshell_*) with every CalculiX reference
# (results/ex4b_n*_l2) and the references with each other: results/comparison.csv.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=$here/results/comparison.csv
rm -f "$out"
refs=("$here"/results/ex4b_n*_l2)
for ref in "${refs[@]}"; do
  [ -f "$ref/load_travel.csv" ] || continue
  for other in "$here"/results/vshell_n* "${refs[@]}"; do
    [ "$other" = "$ref" ] && continue
    python3 "$here/compare.py" "$ref" "$other" --csv "$out" \
      --label "$(basename "$other")_vs_$(basename "$ref")" || true
  done
done
