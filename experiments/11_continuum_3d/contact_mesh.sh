#!/bin/bash
# The mesh convergence of ex4b's force and thickness strain by contact law (README section 5,
# "The contact decides the ratio"): friction 0, Coulomb 0.2 and sticking at 8-32 divisions to
# 10 mm at 0.125 mm steps, two runs at a time on one thread each (accuracy only, not timed);
# curves in results/contact_mesh/f<friction>_n<divisions>/, then contact_mesh.py prints the table
# (each law against its own 32-division run). About 10 min on two cores.
#
#   contact_mesh.sh            # the runs that are missing, then the table
#   contact_mesh.sh --table    # the table only
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
vshell=${VSHELL:-$root/build/app/vshell}
out=$here/results/contact_mesh
mkdir -p "$out"
if [ "${1:-}" != --table ]; then
  for fr in 0 0.2 sticking; do
    for n in 8 12 16 24 32; do
      label=f${fr}_n$n
      [ -f "$out/$label/load_travel.csv" ] && continue
      (
        tmp=$(mktemp -d)
        OMP_NUM_THREADS=1 "$vshell" run "$root/data/scenes/ex4b_square_clamped.toml" \
          --set blank.divisions=$n --set tool.punch.friction=$fr --set process.punch_travel_mm=10 \
          --set "process.output_travels_mm=[5,10]" --set numerics.max_travel_increment_mm=0.125 \
          -o "$tmp/run" > "$tmp/log" 2>&1 || { echo "vshell failed for $label" >&2; exit 1; }
        mkdir -p "$out/$label"
        cp "$tmp"/run/load_travel.csv "$tmp"/run/strains_travel_*mm_{x,diagonal}.csv "$out/$label/"
        rm -rf "$tmp"
        echo "$label done"
      ) &
      if [ "$(jobs -r | wc -l)" -ge 2 ]; then wait -n; fi
    done
  done
  wait
fi
python3 "$here/contact_mesh.py" "$out"
