#!/bin/bash
# The through-thickness normal stress term (numerics.normal_stress, README section 8) against the
# continuum references: results/normal_stress.csv (labels <case>_<none|contact>). About 10 s.
exec "$(dirname "$0")/compare_option.sh" numerics.normal_stress normal_stress.csv none contact
