#!/bin/bash
# Run vshell on the twins of the continuum references and compare (compare.py), writing
# results/comparison.csv (shell against continuum) and results/convergence.csv (continuum mesh
# against the finest). Needs the vshell binary: BUILD_DIR (default ../../build)/app/vshell.
set -euo pipefail
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
  for s in "$@"; do args+=(--set "$s"); done
  "$vshell" run "$scene" "${args[@]}" -o "$scratch/$name" > "$scratch/$name.log" 2>&1
}
shell ex1_mu000 "$ex1" tool.punch.friction=0 "$outs"
shell ex1_mu010 "$ex1" tool.punch.friction=0.1 "$outs"
shell ex1_mu030 "$ex1" tool.punch.friction=0.3 "$outs"
shell ex1_mu010_t0425 "$ex1" tool.punch.friction=0.1 blank.thickness_mm=0.425 "$outs"
shell ex3_r1 "$ex3" material.r_value=1 'process.output_travels_mm=[5,10,13.4391,13.5062,15,20,25,30,35,40]'

rm -f "$res/comparison.csv" "$res/convergence.csv"
cmp() {  # label ref other csv [options]
  local label=$1 ref=$2 other=$3 csv=$4; shift 4
  [ -f "$ref/load_travel.csv" ] || { echo "skip $label (no $ref)"; return 0; }
  [ -f "$other/load_travel.csv" ] || { echo "skip $label (no $other)"; return 0; }
  echo "== $label"
  python3 "$here/compare.py" "$ref" "$other" --label "$label" --csv "$csv" \
    --r0-min 2.9 --r0-max 52.83 "$@"
}
C=$res/comparison.csv
# the continuum runs stopped at 28.2062 (friction 0, 0.3) and 29.2062 mm (0.1): ccx diverged
# (README);
# their last state is compared too (the shell writes outputs there, see $outs)
cmp shell_vs_ex1_mu000 "$res/ex1_mu000_r60_l4" "$scratch/ex1_mu000" "$C" \
    --travels 5,10,15,20,25,28.2062 --strain-travels 10,20,25,28.2062
cmp shell_vs_ex1_mu010 "$res/ex1_mu010_r60_l4" "$scratch/ex1_mu010" "$C" \
    --travels 5,10,15,20,25,29.2062 --strain-travels 10,20,25,29.2062
# the 40 x 4 mesh (convergence run) is the one that reached 30 mm
cmp shell_vs_ex1_mu010_r40 "$res/ex1_mu010_r40_l4" "$scratch/ex1_mu010" "$C" \
    --travels 5,10,15,20,25,30 --strain-travels 10,20,25,30
cmp shell_vs_ex1_mu030 "$res/ex1_mu030_r60_l4" "$scratch/ex1_mu030" "$C" \
    --travels 5,10,15,20,25,28.2062 --strain-travels 10,20,25,28.2062
cmp shell_vs_ex1_mu010_t0425 "$res/ex1_mu010_r60_l2_t0425" "$scratch/ex1_mu010_t0425" "$C" \
    --travels 5,10,15,20,25 --strain-travels 10,20,25
# the cup: the continuum runs stop at 13.5 mm (decks/ex3_mu007_r54_l4_multistep.inp, one step
# per 5 mm) and 13.4391 mm (the one-step deck of gen_deck.py; README section 2)
cmp shell_vs_ex3_mu007_multistep "$res/ex3_mu007_r54_l4_multistep" "$scratch/ex3_r1" "$C" \
    --travels 2,5,10,13.5062 --strain-travels 5,10,13.5062
cmp shell_vs_ex3_mu007 "$res/ex3_mu007_r54_l4" "$scratch/ex3_r1" "$C" \
    --travels 2,5,10,13.4391 --strain-travels 5,10,13.4391
V=$res/convergence.csv
cmp r40_l4_vs_r60_l4 "$res/ex1_mu010_r60_l4" "$res/ex1_mu010_r40_l4" "$V" \
    --travels 5,10,15,20,25 --strain-travels 10,20,25
cmp r60_l2_vs_r60_l4 "$res/ex1_mu010_r60_l4" "$res/ex1_mu010_r60_l2" "$V" \
    --travels 5,10,15,20,25 --strain-travels 10,20,25
cmp mu030_r40_l4_vs_r60_l4 "$res/ex1_mu030_r60_l4" "$res/ex1_mu030_r40_l4" "$V" \
    --travels 5,10,15,20,25 --strain-travels 10,20,25
