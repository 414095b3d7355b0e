#!/usr/bin/env bash
# Runs a fixed set of bundled scenes (both geometries) with the given vshell into DIR/<case>/, so
# that two builds can be compared file by file (bit-identity checks of refactorings):
#   scripts/regress-outputs.sh OLD_VSHELL /tmp/old; scripts/regress-outputs.sh build/app/vshell /tmp/new
#   for f in /tmp/old/*/*.csv; do cmp -s "$f" "/tmp/new/${f#/tmp/old/}" || echo "differs: $f"; done
# ~5 min on 2 cores (the 3D cases dominate).
set -u
V=$1
D=$2
S="$(cd "$(dirname "$0")/.." && pwd)/data/scenes"
mkdir -p "$D"
run() {
  name=$1
  shift
  rm -rf "${D:?}/$name"
  "$V" run "$@" -o "$D/$name" > "$D/$name.log" 2>&1
  echo "$name exit $?"
}
run ex1 "$S/ex1_hemispherical_stretching.toml"
run ex1_mu02 "$S/ex1_hemispherical_stretching.toml" --set tool.punch.friction=0.2
run ex1_stick "$S/ex1_hemispherical_stretching.toml" --set tool.punch.friction=inf
run ex2 "$S/ex2_hemispherical_deep_drawing.toml"
run ex3 "$S/ex3_flat_punch_cup.toml"
run ex3gap "$S/ex3_flat_punch_cup_fixed_gap.toml"
run ex4a_n4_mu02 "$S/ex4a_quarter_disc_sticking.toml" --set blank.divisions=4 \
  --set tool.punch.friction=0.2 --set process.punch_travel_mm=12 --set 'process.output_travels_mm=[6,12]'
run ex4a_n4_stick "$S/ex4a_quarter_disc_sticking.toml" --set blank.divisions=4 \
  --set process.punch_travel_mm=8 --set 'process.output_travels_mm=[4,8]'
run ex4b_n4 "$S/ex4b_square_clamped.toml" --set blank.divisions=4 \
  --set process.punch_travel_mm=6 --set 'process.output_travels_mm=[3,6]'
run ex2_3d "$S/ex2_quarter_disc_deep_drawing_3d.toml" --set process.punch_travel_mm=5 \
  --set 'process.output_travels_mm=[5]'
run ex4a_full "$S/ex4a_full_disc.toml" --set blank.divisions=2 --set process.punch_travel_mm=4 \
  --set 'process.output_travels_mm=[4]'
