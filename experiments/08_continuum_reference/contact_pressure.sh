#!/bin/bash
# The continuum's contact pressure on the punch of ex1 at 25 mm (README section 14): for each
# friction, gen_deck.py's 60 x 4 deck to 25.5 mm with the punch nodes' reactions printed one by
# one (TOTALS=YES), ccx on one thread (about 3 min each), and contact_pressure.py at 25 mm:
# results/contact_pressure_ex1_mu<f>_25mm.csv. A run whose .dat exists is not repeated. Needs ccx.
# Usage: contact_pressure.sh [FRICTION...]   (default 0 0.1 0.3)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
[ $# -gt 0 ] || set -- 0 0.1 0.3
for mu in "$@"; do
  tag=$(printf "%03d" "$(python3 -c "print(round($mu * 100))")")
  name=pressure_ex1_mu$tag
  run=${RUNS_DIR:-$here/runs}/$name
  mkdir -p "$run"
  if [ ! -s "$run/$name.dat" ]; then
    python3 "$here/gen_deck.py" --case ex1 --friction "$mu" --radial 60 --layers 4 --travel 25.5 \
      -o "$run/$name.inp"
    sed -i 's/^\*NODE PRINT, NSET=PUNCH, TOTALS=ONLY$/*NODE PRINT, NSET=PUNCH, TOTALS=YES/' \
      "$run/$name.inp"
    (cd "$run" && OMP_NUM_THREADS=1 CCX_NPROC_EQUATION_SOLVER=1 ccx -i "$name" > ccx.log 2>&1) ||
      echo "ccx exit $? ($name)"
  fi
  python3 "$here/contact_pressure.py" "$run/$name.inp" "$run/$name.dat" 25 \
    > "$here/results/contact_pressure_ex1_mu${tag}_25mm.csv"
  echo "$name -> results/contact_pressure_ex1_mu${tag}_25mm.csv"
done
