#!/bin/bash
# Run one CalculiX case: run_case.sh NAME [gen_deck.py options...]
# Writes runs/NAME/NAME.inp, .dat, ccx.log, and the CSVs of post.py into results/NAME/.
# One thread (OMP_NUM_THREADS=1). Needs ccx (Debian package calculix-ccx) on PATH.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
name=$1; shift
run=${RUNS_DIR:-$here/runs}/$name
mkdir -p "$run"
python3 "$here/gen_deck.py" "$@" -o "$run/$name.inp"
start=$(date +%s)
(cd "$run" && OMP_NUM_THREADS=1 CCX_NPROC_EQUATION_SOLVER=1 ccx -i "$name" > ccx.log 2>&1) || echo "ccx exit $? ($name)"
end=$(date +%s)
echo "$name wall_s=$((end - start))" >> "$run/time.txt"
python3 "$here/post.py" "$run/$name.inp" "$run/$name.dat" -o "$here/results/$name"
echo "$name done in $((end - start)) s"
