#!/usr/bin/env python3
"""Compare a vshell run (or another continuum run) with a continuum reference.

  compare.py REF_DIR OTHER_DIR [--travels 5,10,15,20,25,30] [--strain-travels 10,20,30]
             [--r0-min 0.5] [--csv OUT.csv] [--label NAME]

REF_DIR: results/<case> of post.py (load_travel.csv, strains_travel_<T>mm.csv).
OTHER_DIR: a vshell output folder (load_travel.csv with punch_travel_mm, punch_force_N columns;
strains_travel_<TTT.TT>mm.csv) or another results/<case> folder.
Prints, and appends to --csv, one row per travel: the force of both and the relative error
(other - ref) / ref; at the strain travels the thickness strain of both at the first r0 of OTHER
(the pole point), their difference, and the largest |difference| (and its r0) and the RMS
difference over r0-min <= r0 <= r0-max where both exist. REF is interpolated linearly at OTHER's r0.
Python 3 standard library only.
"""
import argparse
import csv
import glob
import math
import os


def read_csv(path):
    with open(path) as f:
        rows = [ln for ln in f if not ln.startswith("#")]
    return list(csv.DictReader(rows))


def interp(xs, ys, x):
    if x <= xs[0]:
        return ys[0]
    for k in range(1, len(xs)):
        if x <= xs[k]:
            t = (x - xs[k - 1]) / (xs[k] - xs[k - 1]) if xs[k] > xs[k - 1] else 1.0
            return ys[k - 1] + t * (ys[k] - ys[k - 1])
    if x <= xs[-1] + 1e-3:  # the last point of a run that stopped, written rounded
        return ys[-1]
    return float("nan")


def load_curve(d):
    rows = read_csv(os.path.join(d, "load_travel.csv"))
    pts = sorted((float(r["punch_travel_mm"]), float(r["punch_force_N"])) for r in rows)
    # keep the last value at a repeated travel (contact-event steps)
    xs, ys = [], []
    for x, y in pts:
        if xs and abs(x - xs[-1]) < 1e-12:
            ys[-1] = y
        else:
            xs.append(x)
            ys.append(y)
    return xs, ys


def strain_file(d, T):
    for pat in (f"strains_travel_{T:g}mm.csv", f"strains_travel_{T:06.2f}mm.csv"):
        p = os.path.join(d, pat)
        if os.path.exists(p):
            return p
    hits = [p for p in glob.glob(os.path.join(d, "strains_travel_*mm.csv"))
            if abs(float(os.path.basename(p)[15:-6]) - T) < 1e-6]
    if hits:
        return hits[0]
    final = os.path.join(d, "strains_travel_final.csv")  # a continuum run that stopped early
    if os.path.exists(final):
        with open(final) as f:
            first = f.readline()
        if first.startswith("# punch_travel_mm=") and abs(float(first[18:].split()[0]) - T) < 1e-3:
            return final
    return None


def profile(path):
    rows = read_csv(path)
    return ([float(r["r0_mm"]) for r in rows], [float(r["eps_thickness"]) for r in rows])


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("ref")
    p.add_argument("other")
    p.add_argument("--travels", default="5,10,15,20,25,30")
    p.add_argument("--strain-travels", default="10,20,30")
    p.add_argument("--r0-min", type=float, default=0.5)
    p.add_argument("--r0-max", type=float, default=1e9,
                   help="profile errors only for r0 <= this (e.g. exclude the clamped rim)")
    p.add_argument("--csv")
    p.add_argument("--label", default="")
    a = p.parse_args()
    rx, ry = load_curve(a.ref)
    ox, oy = load_curve(a.other)
    out = []
    print(f"{'travel':>6} {'F_ref_N':>9} {'F_other_N':>9} {'dF_%':>6} | {'pole_r0':>7} "
          f"{'e3_ref':>8} {'e3_other':>8} {'de3':>7} {'max|de3|':>8} {'at_r0':>6} {'rms':>6}")
    strain_T = [float(x) for x in a.strain_travels.split(",") if x]
    for T in [float(x) for x in a.travels.split(",") if x]:
        fr, fo = interp(rx, ry, T), interp(ox, oy, T)
        row = dict(label=a.label, punch_travel_mm=T, force_ref_N=round(fr, 2),
                   force_other_N=round(fo, 2), force_error_pct=round(100 * (fo - fr) / fr, 3))
        line = f"{T:6.1f} {fr:9.1f} {fo:9.1f} {row['force_error_pct']:6.2f}"
        pr, po = strain_file(a.ref, T), strain_file(a.other, T)
        if T in strain_T and pr and po:
            r_ref, e_ref = profile(pr)
            r_oth, e_oth = profile(po)
            d = [(r, eo - interp(r_ref, e_ref, r)) for r, eo in zip(r_oth, e_oth)
                 if a.r0_min <= r <= min(a.r0_max, r_ref[-1])]
            d = [(r, x) for r, x in d if not math.isnan(x)]
            pole_r = r_oth[0] if r_oth[0] >= a.r0_min else d[0][0]
            e_r = interp(r_ref, e_ref, pole_r)
            e_o = interp(r_oth, e_oth, pole_r)
            rm, dm = max(d, key=lambda t: abs(t[1]))
            rms = math.sqrt(sum(x * x for _, x in d) / len(d))
            row.update(pole_r0_mm=round(pole_r, 4), eps3_pole_ref=round(e_r, 5),
                       eps3_pole_other=round(e_o, 5), eps3_pole_diff=round(e_o - e_r, 5),
                       eps3_max_abs_diff=round(abs(dm), 5), eps3_max_diff_r0_mm=round(rm, 3),
                       eps3_rms_diff=round(rms, 5))
            line += (f" | {pole_r:7.3f} {e_r:8.4f} {e_o:8.4f} {e_o - e_r:7.4f} {abs(dm):8.4f} "
                     f"{rm:6.1f} {rms:6.4f}")
        print(line)
        out.append(row)
    if a.csv:
        keys = ["label", "punch_travel_mm", "force_ref_N", "force_other_N", "force_error_pct",
                "pole_r0_mm", "eps3_pole_ref", "eps3_pole_other", "eps3_pole_diff",
                "eps3_max_abs_diff", "eps3_max_diff_r0_mm", "eps3_rms_diff"]
        new = not os.path.exists(a.csv)
        with open(a.csv, "a", newline="") as f:
            w = csv.DictWriter(f, fieldnames=keys)
            if new:
                w.writeheader()
            for row in out:
                w.writerow(row)


if __name__ == "__main__":
    main()
