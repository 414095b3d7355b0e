#!/bin/bash
# Run one CalculiX case: run.sh NAME [gen_deck.py options...]
# Writes runs/NAME/NAME.inp, .dat, ccx.log, time.txt, and the CSVs of post.py into results/NAME/.
# One thread (OMP_NUM_THREADS=1); CCX_THREADS=N gives ccx N threads (its equation solver and
# results). Needs ccx (Debian package calculix-ccx) on PATH.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
name=$1; shift
run=${RUNS_DIR:-$here/runs}/$name
mkdir -p "$run"
python3 "$here/gen_deck.py" "$@" -o "$run/$name.inp"
start=$(date +%s)
load0=$(cut -d' ' -f1-3 /proc/loadavg)
threads=${CCX_THREADS:-1}
(cd "$run" && OMP_NUM_THREADS=$threads CCX_NPROC_EQUATION_SOLVER=$threads CCX_NPROC_RESULTS=$threads \
  /usr/bin/time -f "cpu_user_s=%U cpu_sys_s=%S max_rss_kB=%M" ccx -i "$name" > ccx.log 2>&1) \
  || echo "ccx exit $? ($name)"
end=$(date +%s)
echo "$name threads=$threads wall_s=$((end - start)) load_start=\"$load0\" load_end=\"$(cut -d' ' -f1-3 /proc/loadavg)\" $(tail -1 "$run/ccx.log")" >> "$run/time.txt"
python3 "$here/post.py" "$run/$name.inp" "$run/$name.dat" -o "$here/results/$name"
mkdir -p "$here/results/$name" && cp "$run/time.txt" "$here/results/$name/time.txt"
echo "$name done in $((end - start)) s"
