#!/usr/bin/env python3
"""Reference curves for [[discrepancy]] (README section 13): the load and the thickness-strain
profiles at 15 and 25 mm of a CalculiX result folder (../results/<case>), written as
measurement CSVs with their provenance into references/<case>/ (load.csv, thick_15.csv,
thick_25.csv). Run from this folder:

    python3 make_references.py ex1_mu000_K530_n019_r60_l4 ex1_mu030_K530_n019_r60_l4 ...
"""
import csv
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(HERE, "..", "results")


def write(path, source, units, header, rows):
    with open(path, "w") as f:
        f.write(f"# source: {source}\n# units: {units}\n{header}\n")
        for row in rows:
            f.write(",".join(row) + "\n")


def main(cases):
    for case in cases:
        out = os.path.join(HERE, "references", case)
        os.makedirs(out, exist_ok=True)
        source = (f"CalculiX CAX8R continuum reference, experiments/08_continuum_reference/results/"
                  f"{case} (deck: gen_deck.py, README sections 1 and 13)")
        with open(os.path.join(RESULTS, case, "load_travel.csv")) as f:
            rows = [(r["punch_travel_mm"], r["punch_force_N"]) for r in csv.DictReader(f)]
        write(os.path.join(out, "load.csv"), source, "mm, N", "punch_travel_mm,punch_force_N", rows)
        for travel in (15, 25):
            with open(os.path.join(RESULTS, case, f"strains_travel_{travel}mm.csv")) as f:
                rows = [(r["r0_mm"], r["eps_thickness"]) for r in csv.DictReader(f)]
            write(os.path.join(out, f"thick_{travel}.csv"), f"{source}; punch travel {travel} mm",
                  "mm, 1", "r0_mm,eps_thickness", rows)


if __name__ == "__main__":
    main(sys.argv[1:])
