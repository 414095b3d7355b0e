#!/bin/bash
# Smoothness of ex4a's outputs in the punch friction at one Newton tolerance: four runs at
# friction BASE + 0, 1, 2, 3 x 1e-5 to TRAVEL mm, then the largest deviation of the last punch
# force and of the minimum thickness from their least-squares lines ("jitter"), and the lines'
# slopes per 1e-5 of friction, both relative to the mean value (README, "The Newton tolerance of
# 3D runs"). Needs vshell: BUILD_DIR (default ../../build)/app/vshell. About 4 s at 8 divisions.
# SCENE=path runs another scene (DIVISIONS "-": the scene's mesh), e.g. the axisymmetric ex1:
#   SCENE=data/scenes/ex1_hemispherical_stretching.toml tolerance_sweep.sh - 0.1 20 1e-6
# The runs go to a temporary folder (removed at the end), or to SCRATCH if set (kept).
# Usage: tolerance_sweep.sh DIVISIONS BASE TRAVEL TOLERANCE   (e.g. 8 0.1 8 1e-5)
set -euo pipefail
[ $# -eq 4 ] || { sed -n 2,10p "$0"; exit 2; }
d=$1 base=$2 travel=$3 tol=$4
here=$(cd "$(dirname "$0")" && pwd)
vshell=${BUILD_DIR:-$here/../../build}/app/vshell
if [ -n "${SCRATCH:-}" ]; then
  scratch=$SCRATCH
else
  scratch=$(mktemp -d)
  trap 'rm -rf "$scratch"' EXIT
fi
scene=${SCENE:-$here/../../data/scenes/ex4a_quarter_disc_sticking.toml}
mesh=()
[ "$d" = - ] || mesh=(--set blank.divisions="$d")
for i in 0 1 2 3; do
  f=$(python3 -c "print($base + $i * 1e-5)")
  OMP_NUM_THREADS=${OMP_NUM_THREADS:-2} "$vshell" run "$scene" "${mesh[@]}" \
    --set tool.punch.friction="$f" --set process.punch_travel_mm="$travel" \
    --set "process.output_travels_mm=[$travel]" --set numerics.tolerance="$tol" -q \
    -o "$scratch/run_$i" > /dev/null
done
python3 - "$scratch" "$d" "$base" "$travel" "$tol" <<'PY'
import csv, sys
scratch, d, base, travel, tol = sys.argv[1:6]
def last(path):
    rows = [ln for ln in open(path) if not ln.startswith("#")]
    r = list(csv.DictReader(rows))[-1]
    return float(r["punch_force_N"]), float(r["min_thickness_mm"])
vals = [last(f"{scratch}/run_{i}/load_travel.csv") for i in range(4)]
out = []
for k in (0, 1):
    y = [v[k] for v in vals]
    mx, my = 1.5, sum(y) / 4
    b = sum((x - mx) * (yi - my) for x, yi in enumerate(y)) / 5.0
    dev = max(abs(yi - (my + b * (x - mx))) for x, yi in enumerate(y))
    out.append(f"{dev / abs(my):.2e} {b / abs(my):.2e}")
print("divisions base travel_mm tolerance force_jitter force_slope thickness_jitter thickness_slope")
print(d, base, travel, tol, *out)
PY
