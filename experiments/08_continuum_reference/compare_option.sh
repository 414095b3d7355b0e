#!/bin/bash
# One scene option against the continuum references: vshell on the twin scenes with the option at
# each of its values, compared by compare.py into results/<csv> (labels <case>_<value>). Used for
# the normal-stress term (compare_normal_stress.sh, README section 8) and the friction surface
# (compare_friction_surface.sh, section 11). Needs the vshell binary: BUILD_DIR (default
# ../../build)/app/vshell. About 10 s.
# Usage: compare_option.sh KEY CSV VALUE...   (e.g. numerics.normal_stress normal_stress.csv none contact)
# EXTRA_SET="KEY=VALUE ..." adds scene edits to every run (e.g. numerics.normal_stress=contact);
# EX3_SET="KEY=VALUE ..." to the ex3 cup's runs only, after EXTRA_SET (e.g. its own moduli).
set -euo pipefail
[ $# -ge 3 ] || { sed -n 2,7p "$0"; exit 2; }
key=$1 csv=$2
shift 2
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
vshell=${BUILD_DIR:-$root/build}/app/vshell
scratch=${SCRATCH:-$here/runs/shell}
mkdir -p "$scratch"
res=$here/results
ex1=$root/data/scenes/ex1_hemispherical_stretching.toml
ex3=$root/data/scenes/ex3_flat_punch_cup_fixed_gap.toml
outs='process.output_travels_mm=[5,10,15,20,25,28.2062,29.2062,30]'
shell() {  # name scene overrides...
  local name=$1 scene=$2; shift 2
  local args=()
  for s in ${EXTRA_SET:-} "$@"; do args+=(--set "$s"); done
  "$vshell" run "$scene" "${args[@]}" -o "$scratch/$name" > "$scratch/$name.log" 2>&1
}
C=$res/$csv
rm -f "$C"
cmp() {  # label ref other [options]
  local label=$1 ref=$2 other=$3; shift 3
  echo "== $label"
  python3 "$here/compare.py" "$ref" "$other" --label "$label" --csv "$C" \
    --r0-min 2.9 --r0-max 52.83 "$@"
}
for ns in "$@"; do
  o="$key=$ns"
  shell ex1_mu000_$ns "$ex1" tool.punch.friction=0 "$outs" "$o"
  shell ex1_mu010_$ns "$ex1" tool.punch.friction=0.1 "$outs" "$o"
  shell ex1_mu030_$ns "$ex1" tool.punch.friction=0.3 "$outs" "$o"
  shell ex1_mu010_t0425_$ns "$ex1" tool.punch.friction=0.1 blank.thickness_mm=0.425 "$outs" "$o"
  # shellcheck disable=SC2086
  shell ex3_r1_$ns "$ex3" material.r_value=1 'process.output_travels_mm=[2,5,10,13.4391]' "$o" \
    ${EX3_SET:-}
  cmp ex1_mu000_$ns "$res/ex1_mu000_r60_l4" "$scratch/ex1_mu000_$ns" \
    --travels 5,10,15,20,25,28.2062 --strain-travels 10,20,25,28.2062
  cmp ex1_mu010_$ns "$res/ex1_mu010_r60_l4" "$scratch/ex1_mu010_$ns" \
    --travels 5,10,15,20,25,29.2062 --strain-travels 10,20,25,29.2062
  cmp ex1_mu010_r40_$ns "$res/ex1_mu010_r40_l4" "$scratch/ex1_mu010_$ns" \
    --travels 30 --strain-travels 30
  cmp ex1_mu030_$ns "$res/ex1_mu030_r60_l4" "$scratch/ex1_mu030_$ns" \
    --travels 5,10,15,20,25,28.2062 --strain-travels 10,20,25,28.2062
  cmp ex1_mu010_t0425_$ns "$res/ex1_mu010_r60_l2_t0425" "$scratch/ex1_mu010_t0425_$ns" \
    --travels 5,10,15,20,25 --strain-travels 10,20,25
  cmp ex3_mu007_$ns "$res/ex3_mu007_r54_l4" "$scratch/ex3_r1_$ns" \
    --travels 2,5,10 --strain-travels 5,10
done
