#!/usr/bin/env python3
"""The thickness-strain history of the cap (along x): a continuum reference against vshell runs.

  early_history.py REF_DIR SHELL_DIR... [--travels 0.5,1,2,3,5,10,15,20] [--csv OUT.csv]

REF_DIR: results/<case> of post.py (strains_travel_<T>mm_x.csv at the travels); SHELL_DIR: vshell
run folders (strains_travel_<TTT.TT>mm_x.csv). One row per run and travel:
  contact_r0_mm         the largest r0 in contact (continuum: lower-face node within 0.005 mm of
                        the punch; shell: its contact flag)
  e3_r0_<R>mm           thickness strain at r0 = 0, 2.5, 5, 10, 15 mm (linear in r0)
  e3_mean_0_<R>mm       its line average over 0 <= r0 <= 5 and 0 <= r0 <= 15 mm (trapezoids on
                        the profile's own points plus the ends; smooths the node-to-node
                        alternation of both models)
  eps_mid_el1           in-plane log strain of the mid-surface over the first element along x
                        (polyline through the points with r0 <= REF's first element, now against
                        the start)
  punch_force_N         the whole blank's punch force at the travel (load_travel.csv, linear)
  punch_gap_centre_mm   (continuum) the centre's lower-face node's distance from the punch
and for each shell row dforce_percent = (shell - continuum) / continuum and the differences
shell - continuum (d_...), positive: the shell thins less.
Python 3 standard library only.
"""
import argparse
import csv
import math
import os

R0S = (0.0, 2.5, 5.0, 10.0, 15.0)
MEANS = (5.0, 15.0)


def read(path):
    with open(path) as f:
        return list(csv.DictReader(ln for ln in f if not ln.startswith("#")))


def strain_file(d, T):
    for name in (f"strains_travel_{T:g}mm_x.csv", f"strains_travel_{T:06.2f}mm_x.csv"):
        if os.path.exists(os.path.join(d, name)):
            return os.path.join(d, name)
    return None


def at(xs, ys, x):
    for k in range(1, len(xs)):
        if xs[k - 1] - 1e-9 <= x <= xs[k] + 1e-9:
            t = (x - xs[k - 1]) / (xs[k] - xs[k - 1])
            return ys[k - 1] + t * (ys[k] - ys[k - 1])
    return float("nan")


def mean(xs, ys, hi):
    pts = [(x, y) for x, y in zip(xs, ys) if x < hi - 1e-9] + [(hi, at(xs, ys, hi))]
    area = sum(0.5 * (a[1] + b[1]) * (b[0] - a[0]) for a, b in zip(pts, pts[1:]))
    return area / (pts[-1][0] - pts[0][0])


def force(d, T):
    pts = {}
    for r in read(os.path.join(d, "load_travel.csv")):
        pts[float(r["punch_travel_mm"])] = float(r["punch_force_N"])  # last value wins
    xs = sorted(pts)
    return at(xs, [pts[x] for x in xs], T)


def summary(path, el1_mm):
    rows = sorted(read(path), key=lambda r: float(r["r0_mm"]))
    r0 = [float(r["r0_mm"]) for r in rows]
    e3 = [float(r["eps_thickness"]) for r in rows]
    if "contact" in rows[0]:
        inside = [x for x, r in zip(r0, rows) if int(float(r["contact"])) == 1]
    else:
        inside = [x for x, r in zip(r0, rows) if float(r["punch_gap_mm"]) <= 0.005]
    out = {"contact_r0_mm": max(inside) if inside else float("nan")}
    if "punch_gap_mm" in rows[0]:
        out["punch_gap_centre_mm"] = float(rows[0]["punch_gap_mm"])
    for R in R0S:
        out[f"e3_r0_{R:g}mm"] = at(r0, e3, R)
    for R in MEANS:
        out[f"e3_mean_0_{R:g}mm"] = mean(r0, e3, R)
    pts = [(x, float(r["r_mm"]), float(r["z_mm"])) for x, r in zip(r0, rows) if x <= el1_mm + 1e-3]
    now = sum(math.hypot(b[1] - a[1], b[2] - a[2]) for a, b in zip(pts, pts[1:]))
    out["eps_mid_el1"] = math.log(now / (pts[-1][0] - pts[0][0]))
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("ref")
    p.add_argument("shells", nargs="+")
    p.add_argument("--travels", default="0.5,1,2,3,5,10,15,20")
    p.add_argument("--csv", default=None)
    a = p.parse_args()
    travels = [float(t) for t in a.travels.split(",")]
    # the reference's first element along x: its third node column (corner, midside, corner)
    first = sorted(float(r["r0_mm"]) for r in read(strain_file(a.ref, travels[-1])))
    el1 = first[2]
    rows = []
    for T in travels:
        ref = summary(strain_file(a.ref, T), el1)
        F0 = force(a.ref, T)
        rows.append(dict(run=os.path.basename(a.ref.rstrip("/")), punch_travel_mm=T,
                         punch_force_N=F0, **ref))
        for d in a.shells:
            path = strain_file(d, T)
            if path is None:
                continue
            s = summary(path, el1)
            F1 = force(d, T)
            row = dict(run=os.path.basename(d.rstrip("/")), punch_travel_mm=T, punch_force_N=F1,
                       dforce_percent=100.0 * (F1 - F0) / F0, **s)
            row.update({f"d_{k}": s[k] - ref[k] for k in s if k.startswith("e")})
            rows.append(row)
    keys = []
    for r in rows:
        keys += [k for k in r if k not in keys]
    show = ["punch_travel_mm", "punch_force_N", "contact_r0_mm", "e3_r0_0mm", "e3_r0_5mm", "e3_r0_10mm",
            "e3_mean_0_5mm", "e3_mean_0_15mm", "eps_mid_el1"]
    print(f"{'run':<28}" + " ".join(f"{k[:14]:>14}" for k in show))
    for r in rows:
        print(f"{r['run']:<28}" + " ".join(f"{r[k]:14.4f}" for k in show))
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=keys)
            w.writeheader()
            for r in rows:
                w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})


if __name__ == "__main__":
    main()
