#!/usr/bin/env python3
"""Write the stored continuum reference for a quick CI test (ex1, punch friction 0.1).

  make_ci_reference.py [RESULTS_DIR] -> RESULTS_DIR/ci_reference_ex1_mu010.csv

Columns: punch_travel_mm, punch_force_N (continuum, CalculiX, results/ex1_mu010_r60_l4), and the
thickness strain at the second and third element midpoints of the 50-element shell mesh of
ex1_hemispherical_stretching.toml (r0 = 1.7754 and 2.959 mm: the shell's "pole" points; the
continuum is not used below r0 = 1 mm, README section 1), interpolated linearly in r0 from the
continuum profile; rows at 5, 10, ..., 30 mm (as far as the continuum run went).
Python 3 standard library only.
"""
import csv
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
res = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "results")
src = os.path.join(res, "ex1_mu010_r60_l4")
sys.path.insert(0, here)
from compare import interp, load_curve, profile  # noqa: E402

xs, ys = load_curve(src)
POLES = (1.7754, 2.959)
with open(os.path.join(res, "ci_reference_ex1_mu010.csv"), "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["punch_travel_mm", "punch_force_N", "eps_thickness_r0_1.7754mm",
                "eps_thickness_r0_2.959mm"])
    final = os.path.join(src, "strains_travel_final.csv")
    travels = [(T, os.path.join(src, f"strains_travel_{T}mm.csv")) for T in (5, 10, 15, 20, 25, 30)]
    if os.path.exists(final):  # the run stopped before 30 mm: its last state too
        with open(final) as f:
            travels.append((round(float(f.readline()[18:].split()[0]), 4), final))
    for T, p in travels:
        if not os.path.exists(p):
            continue
        r, e = profile(p)
        w.writerow([T, f"{interp(xs, ys, T):.1f}"] + [f"{interp(r, e, x):.5f}" for x in POLES])
