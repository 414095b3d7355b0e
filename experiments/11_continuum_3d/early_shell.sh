#!/bin/bash
# vshell on ex4b at 16 divisions (compare_shell.sh's settings, rigid-plastic and elastic) with the
# early output travels 0.5, 1, 2, 3 mm besides 5-20 (each output travel is also a step end, so the
# steps before 5 mm differ from compare_shell.sh's runs); also the rigid run with a 4x smaller
# step (0.0625 element lengths). Keeps the x/diagonal profiles and the load curve in
# results/vshell_n16_<label>_early/, then writes results/early_history.csv (early_history.py
# against REF, default ex4b_n16_l3_k5e4_mu3). One thread.
# Usage (from anywhere): early_shell.sh [VSHELL] [REF]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
vshell=${1:-$root/build/app/vshell}
ref=$here/results/${2:-ex4b_n16_l3_k5e4_mu3}
scene=$root/data/scenes/ex4b_square_clamped.toml
tmp=${TMPDIR:-/tmp}/vshell_ex4b_early_$$
travels="[0.5,1,2,3,5,10,15,20]"
common=(--set blank.divisions=16 --set numerics.time_integration=implicit --set numerics.start_refinement=0
        --set numerics.contact_events=false --set "process.output_travels_mm=$travels"
        --set numerics.max_travel_increment_mm=0.5)  # the scene's step when measured (0.25 since 27 Nov 2026)
elastic=(--set material.elastic.law=isotropic --set material.elastic.E_MPa=210000
         --set material.elastic.nu=0.3)
for label in rigid elastic rigid_fine; do
  extra=(--set numerics.max_travel_increment_per_length=0.25)
  [ "$label" = elastic ] && extra+=("${elastic[@]}")
  [ "$label" = rigid_fine ] && extra=(--set numerics.max_travel_increment_per_length=0.0625)
  start=$(date +%s)
  OMP_NUM_THREADS=1 "$vshell" run "$scene" "${common[@]}" "${extra[@]}" -o "$tmp/$label" \
    > "$tmp.$label.log" 2>&1
  echo "$label: $(($(date +%s) - start)) s, load $(cut -d' ' -f1 /proc/loadavg)"
  mkdir -p "$here/results/vshell_n16_${label}_early"
  cp "$tmp/$label/load_travel.csv" "$tmp/$label"/strains_travel_*mm_x.csv \
    "$tmp/$label"/strains_travel_*mm_diagonal.csv "$here/results/vshell_n16_${label}_early/"
done
rm -rf "$tmp" "$tmp".*.log
python3 "$here/early_history.py" "$ref" "$here"/results/vshell_n16_*_early \
  --csv "$here/results/early_history.csv"
