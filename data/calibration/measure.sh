#!/bin/sh
# Measures the bundled example fits under a few optimiser settings (the figures in README.md,
# "Status"): forward runs, wall time, identified values and 95 % intervals. Not a test; a few
# minutes on a 2-core machine.
#
#   data/calibration/measure.sh [VSHELL] [CONFIG] [RELATIVE_STEPS] [MODES]
#
# VSHELL default build/app/vshell; CONFIG default calibrate_friction_hardening.toml; RELATIVE_STEPS
# default "0.002 0.01 0.05 0.1"; MODES default "old new" (old: noise_floor_factor = 0 and
# active_set = false, i.e. plain Ceres as before issue 14/15; new: the defaults).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
vshell=${1:-"$root/build/app/vshell"}
config=${2:-calibrate_friction_hardening.toml}
steps=${3:-"0.002 0.01 0.05 0.1"}
modes=${4:-"old new"}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/calibration"
cp "$here"/*.csv "$work/calibration/"
ln -s "$root/data/scenes" "$work/scenes"
echo "uptime: $(uptime)"
echo "config,relative_step,mode,forward_runs,iterations,wall_time_s,noise_floor,termination,values"
for step in $steps; do
  for mode in $modes; do
    case $mode in
      old) extra='noise_floor_factor = 0\nactive_set = false' ;;
      *) extra='' ;;
    esac
    sed "s/^relative_step = .*/relative_step = $step\n$extra/" "$here/$config" \
      > "$work/calibration/run.toml"
    out="$work/out_${step}_$mode"
    "$vshell" calibrate "$work/calibration/run.toml" -o "$out" --quiet > /dev/null || true
    python3 - "$out/calibration.json" "$config" "$step" "$mode" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
values = []
for p in j["parameters"]:
    if p["fixed"]:
        continue
    lo, hi = p.get("interval_lower"), p.get("interval_upper")
    values.append("%s=%.7g [%s, %s]" % (p["address"].split(".")[-1], p["value"],
                  "%.7g" % lo if lo is not None else "-", "%.7g" % hi if hi is not None else "-"))
print("%s,%s,%s,%d,%d,%.1f,%s,%s,%s" % (sys.argv[2], sys.argv[3], sys.argv[4], j["forward_runs"],
      j["iterations"], j["wall_time_s"], j["stopped_at_noise_floor"], j["termination"],
      " ".join(values)))
PY
  done
done
