#!/bin/bash
# Tangential contact on the touching face (numerics.friction_surface, README section 11) against
# the continuum references: results/friction_surface.csv (labels <case>_<mid|face>). About 10 s.
exec "$(dirname "$0")/compare_option.sh" numerics.friction_surface friction_surface.csv mid face
