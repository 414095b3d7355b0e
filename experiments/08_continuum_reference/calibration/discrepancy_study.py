#!/usr/bin/env python3
"""The discrepancy-corrected calibration, leave one out (README section 13).

For each continuum truth (friction 0, 0.1, 0.3; K 589 MPa, n 0.216; ../results/ex1_mu<F>_r60_l4)
the calibration of calibrate_ex1_mu010_discrepancy.toml (shell with the normal-stress term and the
elastic correction; friction, K and n free from 30 % off; load from 10 mm, thickness strain at 15
and 25 mm for r0 >= 2.9 mm; the four [[model_form]] alternatives of section 10) is run

  * uncorrected,
  * corrected by the continuum references at the OTHER two frictions, computed at nominal
    parameters that are not the data's (K 530 MPa, n 0.19: ../results/ex1_mu<F>_K530_n019_r60_l4),
  * corrected by the references at the other two frictions at the data's K and n,

and one CSV row per (truth, variant, parameter) goes to stdout:

    python3 discrepancy_study.py [BUILD_VSHELL] > ../results/calibration_discrepancy.csv

run from this folder (about 2 minutes); the variant configs, data and reports go to a temporary
folder. The data for friction 0.1 are the committed thick_15.csv, thick_25.csv and
load_from10.csv; for 0 and 0.3 they are made the same way from those runs (r0 >= 2.9 mm; the
load from 10 to 25 mm every ~0.5 mm). The references are the CSVs of make_references.py.
"""
import csv
import json
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(HERE, "..", "results")
BASE = "calibrate_ex1_mu010_discrepancy.toml"
FRICTIONS = {"000": 0.0, "010": 0.1, "030": 0.3}
K_TRUE, N_TRUE = 589.0, 0.216


def write_data(folder, tag):
    """thick_15.csv, thick_25.csv, load_from10.csv of continuum run ex1_mu<tag>_r60_l4."""
    case = f"ex1_mu{tag}_r60_l4"
    source = f"# source: CalculiX CAX8R continuum reference ({case})\n"
    for t in (15, 25):
        with open(os.path.join(RESULTS, case, f"strains_travel_{t}mm.csv")) as f:
            rows = [(float(r["r0_mm"]), r["eps_thickness"]) for r in csv.DictReader(f)]
        with open(os.path.join(folder, f"thick_{t}.csv"), "w") as f:
            f.write(source + "# units: mm, 1\nr0_mm,eps_thickness\n")
            for r0, e in rows:
                if r0 >= 2.9:
                    f.write(f"{r0:g},{e}\n")
    with open(os.path.join(RESULTS, case, "load_travel.csv")) as f:
        rows = [(float(r["punch_travel_mm"]), r["punch_force_N"]) for r in csv.DictReader(f)]
    with open(os.path.join(folder, "load_from10.csv"), "w") as f:
        f.write(source + "# units: mm, N\npunch_travel_mm,punch_force_N\n")
        last = -1.0
        for t, force in rows:
            if 10.0 <= t <= 25.0 and t - last >= 0.49:
                f.write(f"{t:g},{force}\n")
                last = t


def config_text(base, folder, tag, references):
    """BASE with its data in `folder` (friction 0.1: the committed files), friction starting 30 %
    off the truth (0.03 for a truth of 0), and the [[discrepancy]] tables replaced by
    `references` [(name, case, friction, K, n)]."""
    truth = FRICTIONS[tag]
    text = base.replace('scene = "../', f'scene = "{HERE}/../')
    text = re.sub(r"\[\[discrepancy\]\].*?(?=\[\[discrepancy\]\]|\[output\])", "", text, flags=re.S)
    text = text.replace("[output]", "".join(
        f'[[discrepancy]]\nname = "{name}"\n'
        f'set = {{ "tool.punch.friction" = {mu}, "material.hardening.K_MPa" = {K}, '
        f'"material.hardening.n" = {n} }}\n'
        f'files = {{ load_from10 = "{HERE}/references/{case}/load.csv", '
        f'thick_15 = "{HERE}/references/{case}/thick_15.csv", '
        f'thick_25 = "{HERE}/references/{case}/thick_25.csv" }}\n'
        for name, case, mu, K, n in references) + "[output]")
    text = re.sub(r'directory = ".*"', 'directory = "out"', text)
    start = 0.7 * truth if truth > 0 else 0.03
    text = re.sub(r'(address = "tool.punch.friction"\ninitial = )[0-9.]+', rf"\g<1>{start}", text)
    if tag != "010":
        for name in ("thick_15.csv", "thick_25.csv", "load_from10.csv"):
            text = text.replace(f'file = "{name}"', f'file = "{os.path.join(folder, name)}"')
    else:
        for name in ("thick_15.csv", "thick_25.csv", "load_from10.csv"):
            text = text.replace(f'file = "{name}"', f'file = "{os.path.join(HERE, name)}"')
    return text


def main():
    vshell = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "../../../build/app/vshell")
    with open(os.path.join(HERE, BASE)) as f:
        base = f.read()
    w = csv.writer(sys.stdout, lineterminator="\n")
    w.writerow(["truth_friction", "variant", "parameter", "truth", "value", "error_pct",
                "interval_lower", "interval_upper", "model_form_lower", "model_form_upper",
                "truth_in_interval", "truth_in_model_form_range", "termination", "forward_runs",
                "lack_of_fit"])
    truths = {"tool.punch.friction": None, "material.hardening.K_MPa": K_TRUE,
              "material.hardening.n": N_TRUE}
    with tempfile.TemporaryDirectory() as tmp:
        for tag, mu in FRICTIONS.items():
            others = [t for t in FRICTIONS if t != tag]
            variants = [
                ("uncorrected", []),
                ("references K 530 n 0.19 at the other frictions",
                 [(f"continuum K530 n0.19 friction {FRICTIONS[o]}", f"ex1_mu{o}_K530_n019_r60_l4",
                   FRICTIONS[o], 530.0, 0.19) for o in others]),
                ("references K 589 n 0.216 at the other frictions",
                 [(f"continuum friction {FRICTIONS[o]}", f"ex1_mu{o}_r60_l4", FRICTIONS[o], K_TRUE,
                   N_TRUE) for o in others]),
            ]
            for k, (label, refs) in enumerate(variants):
                folder = os.path.join(tmp, f"{tag}_{k}")
                os.makedirs(folder)
                write_data(folder, tag)
                path = os.path.join(folder, "config.toml")
                with open(path, "w") as f:
                    f.write(config_text(base, folder, tag, refs))
                subprocess.run([vshell, "calibrate", path, "-o", os.path.join(folder, "out")],
                               check=True, stdout=subprocess.DEVNULL, cwd=folder)
                with open(os.path.join(folder, "out", "calibration.json")) as f:
                    j = json.load(f)
                verdicts = ";".join(f"{d['name']}:{d['lack_of_fit']['verdict']}"
                                    for d in j["data_sets"])
                for p in j["parameters"]:
                    truth = truths[p["address"]] if truths[p["address"]] is not None else mu
                    lo, hi = p.get("interval_lower"), p.get("interval_upper")
                    mlo, mhi = p.get("model_form_lower"), p.get("model_form_upper")
                    err = 100.0 * (p["value"] - truth) / truth if truth else float("nan")
                    w.writerow([mu, label, p["address"], truth, f"{p['value']:.6g}",
                                "" if truth == 0 else f"{err:.2f}",
                                "" if lo is None else f"{lo:.6g}", "" if hi is None else f"{hi:.6g}",
                                "" if mlo is None else f"{mlo:.6g}", "" if mhi is None else f"{mhi:.6g}",
                                lo is not None and lo <= truth <= hi,
                                mlo is not None and mlo <= truth <= mhi,
                                j["termination"], j["forward_runs"], verdicts])
                    sys.stdout.flush()


if __name__ == "__main__":
    main()
