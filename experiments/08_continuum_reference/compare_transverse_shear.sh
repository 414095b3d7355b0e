#!/bin/bash
# The transverse-shear penalty's scale (numerics.transverse_shear_scale, README section 14) against
# the continuum references, plane stress and with the normal-stress term:
# results/transverse_shear.csv (labels <case>_<scale>) and results/transverse_shear_contact.csv.
# About 30 s.
set -euo pipefail
here=$(dirname "$0")
"$here/compare_option.sh" numerics.transverse_shear_scale transverse_shear.csv 0.1 0.3 1 3 10
EXTRA_SET=numerics.normal_stress=contact SCRATCH="$here/runs/shell_contact" \
  "$here/compare_option.sh" numerics.transverse_shear_scale transverse_shear_contact.csv \
  0.1 0.3 1 3 10
# With the elastic start as well (README section 14, "The closest combination"): the term and
# the continuum's moduli for the start (ex1 E 210 GPa, nu 0.3; the ex3 cup 70 GPa, 0.33 and the
# continuum's 1.04 mm holder gap, as compare_elastic.sh), strains plastic only:
# results/transverse_shear_elastic.csv (labels <case>_<scale>), and at 30 / 50 / 80 elements
# with the factor 0.3: results/transverse_shear_elastic_mesh.csv (labels <case>_<elements>).
# shellcheck source=elastic_settings.sh
. "$here/elastic_settings.sh"
EXTRA_SET="numerics.normal_stress=contact $elastic" EX3_SET=$cup \
  SCRATCH="$here/runs/shell_elastic_shear" \
  "$here/compare_option.sh" numerics.transverse_shear_scale transverse_shear_elastic.csv 0.3 0.5 1
EXTRA_SET="numerics.normal_stress=contact $elastic numerics.transverse_shear_scale=0.3" \
  EX3_SET=$cup SCRATCH="$here/runs/shell_elastic_mesh" \
  "$here/compare_option.sh" blank.elements transverse_shear_elastic_mesh.csv 30 50 80
# Mesh study (README section 14): ex1 with the normal-stress term at 30, 50 and 100 elements,
# friction 0.1 and 0.3: results/transverse_shear_mesh.csv (labels ex1_mu<f>_e<elements>_<scale>).
res=$here/results
C=$res/transverse_shear_mesh.csv
rm -f "$C"
vshell=${BUILD_DIR:-$here/../../build}/app/vshell
scratch=$here/runs/shell_mesh
mkdir -p "$scratch"
ex1=$here/../../data/scenes/ex1_hemispherical_stretching.toml
for mu in 010 030; do
  for ne in 30 50 100; do
    for s in 0.1 0.3 1; do
      name=ex1_mu${mu}_e${ne}_$s
      "$vshell" run "$ex1" --set tool.punch.friction=0.${mu#0} --set blank.elements=$ne \
        --set numerics.normal_stress=contact --set numerics.transverse_shear_scale=$s \
        --set 'process.output_travels_mm=[10,20,25,28.2062,29.2062]' \
        -o "$scratch/$name" > "$scratch/$name.log" 2>&1
      last=$([ $mu = 010 ] && echo 29.2062 || echo 28.2062)
      python3 "$here/compare.py" "$res/ex1_mu${mu}_r60_l4" "$scratch/$name" --label "$name" \
        --csv "$C" --r0-min 2.9 --r0-max 52.83 --travels 10,20,25,$last \
        --strain-travels 10,20,25,$last > /dev/null
    done
  done
done
