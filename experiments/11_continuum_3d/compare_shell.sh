#!/bin/bash
# Run vshell on ex4b (divisions 8 and 16; rigid-plastic and with the elastic correction; sticking
# on the mid-surface, the default, and with numerics.friction_surface = face, label suffix _face) and
# compare each run with the CalculiX references of results/ (compare_all.sh: results/comparison.csv);
# writes results/vshell_times.csv and keeps each vshell run's load_travel.csv and x/diagonal strain
# profiles in results/vshell_<label>/.
# Usage (from anywhere): compare_shell.sh [VSHELL]   (default: build/app/vshell of this tree)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
vshell=${1:-$root/build/app/vshell}
scene=$root/data/scenes/ex4b_square_clamped.toml
tmp=${TMPDIR:-/tmp}/vshell_ex4b_$$
common=(--set numerics.time_integration=implicit --set numerics.start_refinement=0 --set numerics.max_travel_increment_per_length=0.25
        --set numerics.contact_events=false
        --set numerics.max_travel_increment_mm=0.5)  # the scene's step when measured (0.25 since 27 Nov 2026)
elastic=(--set material.elastic.law=isotropic --set material.elastic.E_MPa=210000
         --set material.elastic.nu=0.3)
echo "label,divisions,elastic,wall_s,load_1min" > "$here/results/vshell_times.csv"
for n in 8 16; do
  for el in rigid elastic rigid_face elastic_face; do
    label=n${n}_${el}
    extra=()
    case $el in elastic*) extra=("${elastic[@]}") ;; esac
    case $el in *_face) extra+=(--set numerics.friction_surface=face) ;; esac
    load=$(cut -d' ' -f1 /proc/loadavg)
    start=$(date +%s.%N)
    "$vshell" run "$scene" --set blank.divisions=$n "${common[@]}" "${extra[@]}" -o "$tmp/$label" > "$tmp.$label.log" 2>&1
    end=$(date +%s.%N)
    printf "%s,%s,%s,%.1f,%s\n" "$label" "$n" "$el" "$(echo "$end - $start" | bc)" "$load" >> "$here/results/vshell_times.csv"
    mkdir -p "$here/results/vshell_$label"
    cp "$tmp/$label/load_travel.csv" "$tmp/$label"/strains_travel_*mm_x.csv "$tmp/$label"/strains_travel_*mm_diagonal.csv "$here/results/vshell_$label/"
  done
done
rm -rf "$tmp" "$tmp".*.log
cat "$here/results/vshell_times.csv"
"$here/compare_all.sh"
