#!/usr/bin/env python3
"""How the identified friction depends on which thickness points enter (README section 10,
"Which thickness points"). Variants of calibrate_ex1_mu010_contact_elastic_from10.toml (full
elastic correction, normal-stress term, load from 10 mm), each a few seconds:

  * the pole region left out: only r0 >= 5, 10, 15, 20 mm of both thickness profiles;
  * weighted by the continuum's resolution: a sigma per point from the reference's own mesh and
    layer convergence (|40x4 - 60x4| and |60x2 - 60x4| combined, at least 1e-4), the load at
    20 N or at its default sigma (281.3 N, 1 % of its range);
  * one profile alone (15 or 25 mm).

    python3 thickness_points.py [BUILD_VSHELL] > ../results/calibration_thickness_points.csv

run from this folder; the variant configs, data and reports go to a temporary folder.
"""
import bisect
import csv
import json
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(HERE, "..", "results")
BASE = "calibrate_ex1_mu010_contact_elastic_from10.toml"
TRUTH = {"tool.punch.friction": 0.1, "material.hardening.K_MPa": 589.0, "material.hardening.n": 0.216}


def read_profile(path):
    """(header lines, [(r0, eps)]) of a measurement CSV."""
    header, rows = [], []
    with open(path) as f:
        for line in f:
            line = line.rstrip("\r\n")
            if line.startswith("#") or line.startswith("r0_mm"):
                header.append(line)
            elif line:
                r0, eps = line.split(",")[:2]
                rows.append((float(r0), float(eps)))
    return header, rows


def reference_profile(case, travel):
    with open(os.path.join(RESULTS, case, f"strains_travel_{travel}mm.csv")) as f:
        rows = list(csv.DictReader(f))
    return [float(r["r0_mm"]) for r in rows], [float(r["eps_thickness"]) for r in rows]


def interpolate(x, y, at):
    i = bisect.bisect_left(x, at)
    if i <= 0:
        return y[0]
    if i >= len(x):
        return y[-1]
    return y[i - 1] + (y[i] - y[i - 1]) * (at - x[i - 1]) / (x[i] - x[i - 1])


def resolution(travel, r0):
    """The continuum's own resolution of its thickness strain at r0 (section 3)."""
    fine = reference_profile("ex1_mu010_r60_l4", travel)
    radial = reference_profile("ex1_mu010_r40_l4", travel)
    layers = reference_profile("ex1_mu010_r60_l2", travel)
    e = interpolate(*fine, r0)
    d = ((interpolate(*radial, r0) - e) ** 2 + (interpolate(*layers, r0) - e) ** 2) ** 0.5
    return max(d, 1e-4)


def write_profile(path, header, rows, sigma=None):
    with open(path, "w") as f:
        for line in header:
            if line.startswith("r0_mm"):
                line = "r0_mm,eps_thickness" + (",sigma" if sigma else "")
            f.write(line + "\n")
        for r0, eps in rows:
            extra = f",{sigma(r0):.6g}" if sigma else ""
            f.write(f"{r0:g},{eps:.6f}{extra}\n")


def variant_config(base_text, folder, files, load_sigma=None, drop=()):
    """The base config with its data files replaced by `files` (name -> path); data sets named
    in `drop` removed; the scene path made absolute."""
    text = base_text.replace('scene = "../', f'scene = "{HERE}/../')
    blocks = text.split("[[data]]")
    out = [blocks[0]]
    for block in blocks[1:]:
        name = re.search(r'file = "([^"]+)"', block).group(1)
        if name in drop:
            # keep what follows the data set (optimizer, forward, ...) after its last key
            rest = block.split("\n[", 1)
            out.append("" if len(rest) == 1 else "\n[" + rest[1])
            continue
        block = block.replace(f'file = "{name}"', f'file = "{files.get(name, os.path.join(HERE, name))}"')
        if load_sigma and name.startswith("load"):
            block = block.replace('kind = "load_travel"', f'kind = "load_travel"\nsigma = {load_sigma}')
        out.append("[[data]]" + block)
    text = "".join(out)
    # No model-form refits here: the main fit only.
    text = text.split("# Model-form alternatives")[0]
    path = os.path.join(folder, "config.toml")
    with open(path, "w") as f:
        f.write(text + '[output]\ndirectory = "out"\n')
    return path


def main():
    vshell = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "../../../build/app/vshell")
    with open(os.path.join(HERE, BASE)) as f:
        base_text = f.read()
    profiles = {t: read_profile(os.path.join(HERE, f"thick_{t}.csv")) for t in (15, 25)}
    # (label, smallest r0, thickness sigma per point, load sigma in N (None: default), dropped)
    variants = [("all r0 >= 2.9 mm (section 10)", 2.9, False, None, ())]
    variants += [(f"r0 >= {r} mm", r, False, None, ()) for r in (5, 10, 15, 20)]
    variants += [("sigma per point from the continuum's resolution, load 20 N", 2.9, True, 20.0, ()),
                 ("r0 >= 10 mm, sigma per point, load 20 N", 10, True, 20.0, ()),
                 # the load's default sigma (1 % of its range): the thickness weighting alone
                 ("sigma per point, load 281.3 N", 2.9, True, 281.3, ()),
                 ("thickness at 15 mm only", 2.9, False, None, ("thick_25.csv",)),
                 ("thickness at 25 mm only", 2.9, False, None, ("thick_15.csv",))]
    w = csv.writer(sys.stdout, lineterminator="\r\n")  # the stored results have CRLF line ends
    w.writerow(["variant", "thickness_points", "friction", "friction_lower", "friction_upper",
                "friction_error_pct", "K_MPa", "K_error_pct", "n", "n_error_pct", "termination", "forward_runs",
                "lack_of_fit"])
    with tempfile.TemporaryDirectory() as tmp:
        for k, (label, r_min, per_point, load_sigma, drop) in enumerate(variants):
            folder = os.path.join(tmp, str(k))
            os.makedirs(folder)
            files, points = {}, 0
            for t, (header, rows) in profiles.items():
                kept = [(r0, e) for r0, e in rows if r0 >= r_min - 1e-9]
                name = f"thick_{t}.csv"
                if name not in drop:
                    points += len(kept)
                files[name] = os.path.join(folder, name)
                write_profile(files[name], header, kept,
                              (lambda r0, t=t: resolution(t, r0)) if per_point else None)
            config = variant_config(base_text, folder, files, load_sigma, drop)
            subprocess.run([vshell, "calibrate", config, "-o", os.path.join(folder, "out")],
                           check=True, stdout=subprocess.DEVNULL, cwd=folder)
            with open(os.path.join(folder, "out", "calibration.json")) as f:
                j = json.load(f)
            p = {q["address"]: q for q in j["parameters"]}
            err = {a: 100.0 * (p[a]["value"] - TRUTH[a]) / TRUTH[a] for a in TRUTH}
            fr = p["tool.punch.friction"]
            verdicts = ";".join(f"{d['name']}:{d['lack_of_fit']['verdict']}" for d in j["data_sets"])
            w.writerow([label, points, f"{fr['value']:.6g}", f"{fr['interval_lower']:.6g}",
                        f"{fr['interval_upper']:.6g}", f"{err['tool.punch.friction']:.2f}",
                        f"{p['material.hardening.K_MPa']['value']:.6g}",
                        f"{err['material.hardening.K_MPa']:.2f}",
                        f"{p['material.hardening.n']['value']:.6g}",
                        f"{err['material.hardening.n']:.2f}", j["termination"], j["forward_runs"],
                        verdicts])
            sys.stdout.flush()


if __name__ == "__main__":
    main()
