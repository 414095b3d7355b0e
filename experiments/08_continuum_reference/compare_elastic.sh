#!/bin/bash
# The elastic correction ([material.elastic], README section 10) against the continuum
# references, with numerics.normal_stress = "contact": vshell on the twin scenes with elasticity
# off (off), only the elastic part of the strains (strains), only the elastic start (start) and
# both (both), compared by compare.py into results/elastic.csv (labels <case>_<variant>). The
# moduli are the continuum's: ex1 E 210 GPa, nu 0.3; ex3 E 70 GPa, nu 0.33 (R = 1 and the
# continuum's 1.04 mm holder gap: the bundled fixed-gap cup now has 1.2 mm). Needs the vshell
# binary: BUILD_DIR (default ../../build)/app/vshell. About 30 s.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
vshell=${BUILD_DIR:-$root/build}/app/vshell
scratch=${SCRATCH:-$here/runs/shell_elastic}
mkdir -p "$scratch"
res=$here/results
ex1=$root/data/scenes/ex1_hemispherical_stretching.toml
ex3=$root/data/scenes/ex3_flat_punch_cup_fixed_gap.toml
outs='process.output_travels_mm=[5,10,15,20,25,28.2062,29.2062,30]'
shell() {  # name scene overrides...
  local name=$1 scene=$2; shift 2
  local args=()
  for s in "$@"; do args+=(--set "$s"); done
  "$vshell" run "$scene" "${args[@]}" -o "$scratch/$name" > "$scratch/$name.log" 2>&1
}
variant() {  # variant E nu -> the --set arguments
  local v=$1 E=$2 nu=$3
  case $v in
    off) ;;
    strains) echo "material.elastic.law=isotropic material.elastic.E_MPa=$E material.elastic.nu=$nu material.elastic.start=false" ;;
    start) echo "material.elastic.law=isotropic material.elastic.E_MPa=$E material.elastic.nu=$nu material.elastic.strains=false" ;;
    both) echo "material.elastic.law=isotropic material.elastic.E_MPa=$E material.elastic.nu=$nu" ;;
  esac
}
C=$res/elastic.csv
rm -f "$C"
cmp() {  # label ref other [options]
  local label=$1 ref=$2 other=$3; shift 3
  echo "== $label"
  python3 "$here/compare.py" "$ref" "$other" --label "$label" --csv "$C" \
    --r0-min 2.9 --r0-max 52.83 "$@"
}
ns="numerics.normal_stress=contact"
for v in off strains start both; do
  # shellcheck disable=SC2046
  e1=$(variant $v 210000 0.3); e3=$(variant $v 70000 0.33)
  shell ex1_mu000_$v "$ex1" tool.punch.friction=0 "$outs" "$ns" $e1
  shell ex1_mu010_$v "$ex1" tool.punch.friction=0.1 "$outs" "$ns" $e1
  shell ex1_mu030_$v "$ex1" tool.punch.friction=0.3 "$outs" "$ns" $e1
  shell ex3_r1_$v "$ex3" material.r_value=1 tool.holder.gap_mm=1.04 \
    'process.output_travels_mm=[2,5,10,13.4391]' "$ns" $e3
  cmp ex1_mu000_$v "$res/ex1_mu000_r60_l4" "$scratch/ex1_mu000_$v" \
    --travels 5,10,15,20,25,28.2062 --strain-travels 10,15,20,25,28.2062
  cmp ex1_mu010_$v "$res/ex1_mu010_r60_l4" "$scratch/ex1_mu010_$v" \
    --travels 5,10,15,20,25,29.2062 --strain-travels 10,15,20,25,29.2062
  cmp ex1_mu030_$v "$res/ex1_mu030_r60_l4" "$scratch/ex1_mu030_$v" \
    --travels 5,10,15,20,25,28.2062 --strain-travels 10,15,20,25,28.2062
  cmp ex3_mu007_$v "$res/ex3_mu007_r54_l4" "$scratch/ex3_r1_$v" \
    --travels 2,5,10 --strain-travels 5,10
done
