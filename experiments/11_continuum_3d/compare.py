#!/usr/bin/env python3
"""Compare a vshell 3D run (or another continuum run) with a continuum reference of this folder.

  compare.py REF_DIR OTHER_DIR [--travels 5,10,15,20] [--lines x,diagonal] [--r0-min-mm 0] [--r0-max-mm 50]
             [--label NAME] [--csv OUT.csv]

REF_DIR: results/<case> of post.py (load_travel.csv; strains_travel_<T>mm_<line>.csv).
OTHER_DIR: a vshell run folder (load_travel.csv; strains_travel_<TTT.TT>mm_<line>.csv, whose
r0_mm is the initial distance from the axis along the line) or another results/<case> folder.
Prints one row per travel: both forces and (other - ref) / ref; for each line, the thickness
strain of both at the centre (r0 = 0), the largest |other - ref| (and its r0) and the RMS
difference for r0-min <= r0 <= r0-max (along x; along the diagonal r0 <= sqrt 2 r0-max; the default
50 mm leaves out the clamp's last 1.5 elements at 16 divisions, where the bricks' thickness strain
alternates between corner and midside nodes, README), compared at the
points of the coarser of the two profiles (the finer one is interpolated linearly). Positive
de3 = OTHER thins less. Python 3 standard library only.
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
    if x < xs[0] - 1e-6 or x > xs[-1] + 1e-6:
        return float("nan")
    for k in range(1, len(xs)):
        if x <= xs[k] + 1e-9:
            t = (x - xs[k - 1]) / (xs[k] - xs[k - 1]) if xs[k] > xs[k - 1] else 1.0
            return ys[k - 1] + t * (ys[k] - ys[k - 1])
    return ys[-1]


def load_curve(d):
    pts = {}
    for r in read_csv(os.path.join(d, "load_travel.csv")):
        pts[float(r["punch_travel_mm"])] = float(r["punch_force_N"])  # last value wins
    xs = sorted(pts)
    return xs, [pts[x] for x in xs]


def strain_file(d, T, line):
    for pat in (f"strains_travel_{T:g}mm_{line}.csv", f"strains_travel_{T:06.2f}mm_{line}.csv"):
        p = os.path.join(d, pat)
        if os.path.exists(p):
            return p
    return None


def profile(path):
    rows = read_csv(path)
    pts = sorted((float(r["r0_mm"]), float(r["eps_thickness"])) for r in rows)
    return [p[0] for p in pts], [p[1] for p in pts]


def profile_pairs(ref_path, other_path, rmin, rmax):
    """(r0, ref, other) thickness strains at the points of the coarser of the two profiles (the
    finer one interpolated linearly), rmin <= r0 <= rmax, points outside either profile dropped."""
    rx, ry = profile(ref_path)
    qx, qy = profile(other_path)
    if len(rx) <= len(qx):
        pts = [(r, e, interp(qx, qy, r)) for r, e in zip(rx, ry) if rmin - 1e-6 <= r <= rmax + 1e-6]
    else:
        pts = [(r, interp(rx, ry, r), e) for r, e in zip(qx, qy) if rmin - 1e-6 <= r <= rmax + 1e-6]
    return [t for t in pts if not math.isnan(t[2]) and not math.isnan(t[1])]


def line_difference(ref, other, T, line, r0_max_mm=50.0):
    """(RMS, largest |d|) of the thickness-strain difference other - ref at travel T along line
    (x: r0 <= r0_max_mm; diagonal: r0 <= sqrt 2 r0_max_mm), at the coarser profile's points."""
    rmax = r0_max_mm * (math.sqrt(2.0) if line == "diagonal" else 1.0)
    pts = profile_pairs(strain_file(ref, T, line), strain_file(other, T, line), 0.0, rmax)
    d = [o - e for _, e, o in pts]
    return math.sqrt(sum(x * x for x in d) / len(d)), max(abs(x) for x in d)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("ref")
    p.add_argument("other")
    p.add_argument("--travels", default="5,10,15,20")
    p.add_argument("--lines", default="x,diagonal")
    p.add_argument("--r0-max-mm", type=float, default=50.0)
    p.add_argument("--r0-min-mm", type=float, default=0.0)
    p.add_argument("--label", default=None)
    p.add_argument("--csv", default=None, help="append the rows to this CSV")
    a = p.parse_args()
    label = (a.label or f"{os.path.basename(a.other.rstrip('/'))}_vs_{os.path.basename(a.ref.rstrip('/'))}")
    if a.r0_min_mm > 0.0:
        label += f"_r0min{a.r0_min_mm:g}"
    fx, fy = load_curve(a.ref)
    ox, oy = load_curve(a.other)
    lines = a.lines.split(",")
    rows = []
    print(f"{label}")
    hdr = f"{'T':>5} {'F_ref':>9} {'F_other':>9} {'dF%':>7}"
    for ln in lines:
        hdr += f" | {ln}: {'e3c_ref':>8} {'e3c_oth':>8} {'maxabs':>7} {'at_r0':>6} {'rms':>7}"
    print(hdr)
    for T in [float(t) for t in a.travels.split(",")]:
        F0, F1 = interp(fx, fy, T), interp(ox, oy, T)
        row = dict(label=label, punch_travel_mm=T, force_ref_N=F0, force_other_N=F1,
                   dforce_percent=100.0 * (F1 - F0) / F0)
        out = f"{T:5g} {F0:9.1f} {F1:9.1f} {row['dforce_percent']:+7.2f}"
        for ln in lines:
            pr, po = strain_file(a.ref, T, ln), strain_file(a.other, T, ln)
            if not (pr and po):
                out += f" | {ln}: missing"
                continue
            rmax = a.r0_max_mm * (math.sqrt(2.0) if ln == "diagonal" else 1.0)
            pts = profile_pairs(pr, po, a.r0_min_mm, rmax)
            rx, ry = profile(pr)
            qx, qy = profile(po)
            d = [(abs(o - e), r, o - e) for r, e, o in pts]
            worst = max(d)
            rms = math.sqrt(sum(x[2] ** 2 for x in d) / len(d))
            c_ref, c_oth = interp(rx, ry, 0.0), interp(qx, qy, 0.0)
            row.update({f"e3_centre_ref_{ln}": c_ref, f"e3_centre_other_{ln}": c_oth,
                        f"max_abs_de3_{ln}": worst[0], f"max_at_r0_mm_{ln}": worst[1],
                        f"signed_de3_at_max_{ln}": worst[2], f"rms_de3_{ln}": rms})
            out += (f" | {ln}: {c_ref:8.4f} {c_oth:8.4f} {worst[2]:+7.4f} {worst[1]:6.1f} "
                    f"{rms:7.4f}")
        print(out)
        rows.append(row)
    if a.csv:
        keys = []
        for r in rows:
            keys += [k for k in r if k not in keys]
        new = not os.path.exists(a.csv)
        with open(a.csv, "a", newline="") as f:
            w = csv.DictWriter(f, fieldnames=keys)
            if new:
                w.writeheader()
            for r in rows:
                w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})


if __name__ == "__main__":
    main()
