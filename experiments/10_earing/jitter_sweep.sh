#!/bin/bash
# Smoothness of the cup-height profile in one parameter (what a finite-difference calibration
# sees): runs SCENE at PARAM = X0 + k H for k = 0 .. N-1 (one OpenMP thread each, one at a time)
# and prints, per rim point, the largest deviation from the least-squares line through the N
# heights (jitter_sweep.py).
#   jitter_sweep.sh SCENE PARAM X0 H N OUT [--set KEY=VALUE ...]
# e.g. experiments/10_earing/jitter_sweep.sh data/calibration/esaform_cup_3d_hill48_quarter.toml \
#        material.anisotropy.r45 0.45 0.001 5 /tmp/jitter --set material.anisotropy.r90=0.45
# (jitter_sweep.py OUT [FD_STEP] re-reads a finished sweep; FD_STEP, default 0.01, is the
# calibration's finite-difference step in the parameter, to compare the jitter with.)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
scene=$1 param=$2 x0=$3 h=$4 n=$5 out=$6
shift 6
mkdir -p "$out"
for ((k = 0; k < n; ++k)); do
  x=$(python3 -c "print(repr($x0 + $k * $h))")
  OMP_NUM_THREADS=1 "$root/build/app/vshell" run "$scene" --set "$param=$x" "$@" -q \
    -o "$out/run_$k" > "$out/run_$k.log" 2>&1 || echo "run $k ($param = $x) failed"
  echo "$k $x" >> "$out/values.txt"
done
python3 "$here/jitter_sweep.py" "$out" | tee "$out/jitter.txt"
