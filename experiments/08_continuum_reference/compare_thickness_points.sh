#!/bin/bash
# The Simpson points through the thickness (numerics.thickness_points, default 5) against the
# continuum references (README section 14, "The thickness points on the cup's nose"): with the
# normal-stress term at 3 / 5 / 9 points, results/thickness_points_contact.csv; with the
# closest combination of section 14 (the term, the elastic start, strains plastic only) at the
# penalty factor 1 and 0.3, at 5 / 7 / 9 points, results/thickness_points_elastic_ts1.csv and
# results/thickness_points_elastic_ts03.csv (labels <case>_<points>). About 1 minute.
set -euo pipefail
here=$(dirname "$0")
EXTRA_SET=numerics.normal_stress=contact SCRATCH="$here/runs/shell_points" \
  "$here/compare_option.sh" numerics.thickness_points thickness_points_contact.csv 3 5 9
# shellcheck source=elastic_settings.sh
. "$here/elastic_settings.sh"
EXTRA_SET="numerics.normal_stress=contact $elastic" EX3_SET=$cup \
  SCRATCH="$here/runs/shell_points_ts1" \
  "$here/compare_option.sh" numerics.thickness_points thickness_points_elastic_ts1.csv 5 7 9
EXTRA_SET="numerics.normal_stress=contact $elastic numerics.transverse_shear_scale=0.3" \
  EX3_SET=$cup SCRATCH="$here/runs/shell_points_ts03" \
  "$here/compare_option.sh" numerics.thickness_points thickness_points_elastic_ts03.csv 5 7 9
