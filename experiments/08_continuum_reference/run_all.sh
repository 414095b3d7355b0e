#!/bin/bash
# Regenerate every continuum reference of this folder (CalculiX, one thread per run, JOBS runs
# at a time; about 2-3 CPU-hours in all) and then the shell comparison (compare_shell.sh).
# Needs: ccx (Debian package calculix-ccx), python3. Usage: run_all.sh [CASE...]
set -uo pipefail
cd "$(dirname "$0")"
JOBS=${JOBS:-2}
# name | gen_deck.py options
cases=(
  "ex1_mu000_r60_l4|--case ex1 --friction 0 --radial 60 --layers 4"
  "ex1_mu010_r60_l4|--case ex1 --friction 0.1 --radial 60 --layers 4"
  "ex1_mu030_r60_l4|--case ex1 --friction 0.3 --radial 60 --layers 4"
  "ex1_mu010_r40_l4|--case ex1 --friction 0.1 --radial 40 --layers 4"
  "ex1_mu030_r40_l4|--case ex1 --friction 0.3 --radial 40 --layers 4"
  "ex1_mu010_r60_l2|--case ex1 --friction 0.1 --radial 60 --layers 2"
  "ex1_mu010_r60_l2_t0425|--case ex1 --friction 0.1 --radial 60 --layers 2 --thickness 0.425"
  "ex3_mu007_r54_l4|--case ex3 --friction 0.07 --radial 54 --layers 4 --travel 40"
  "ex3_mu007_r54_l4_E210|--case ex3 --friction 0.07 --radial 54 --layers 4 --travel 10.2 --E 210000 --max-increment-mm 0.1"
)
run() { local name=${1%%|*} opts=${1#*|}; ./run_case.sh "$name" $opts; }
for c in "${cases[@]}"; do
  name=${c%%|*}
  if [ $# -gt 0 ] && ! printf '%s\n' "$@" | grep -qx "$name"; then continue; fi
  while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do sleep 5; done
  run "$c" &
done
wait
./compare_shell.sh
