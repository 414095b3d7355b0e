#!/usr/bin/env python3
"""Read a CalculiX .dat written by a gen_deck.py deck (ex4b 3D quarter) and write the result CSVs.

  <out>/load_travel.csv                    punch_travel_mm, punch_force_N (whole blank: 4 x the
                                           quarter's punch reaction; every converged increment)
  <out>/strains_travel_<T>mm_<line>.csv    x0_mm, y0_mm, r0_mm, r_mm, z_mm, thickness_mm,
                                           eps_thickness at the output travels, line = x (y = 0),
                                           y (x = 0), diagonal (x = y), punch_gap_mm
  <out>/strains_travel_final_<line>.csv    the same at the last converged increment if the run
                                           stopped before its final travel (travel in a comment)

Punch travel = step time x final travel (one step, linear ramp). The strains at an output travel
come from the face-node displacements interpolated linearly between the two increments around it.

Thickness at a through-thickness material line (lower face node b, upper face node t; r0 its
initial distance from the punch axis along the line): the line lies in a symmetry plane (x = 0,
y = 0, or x = y), so the mid-surface normal lies in that plane too; with s the coordinate along
the line's plane (s = x, y or (x + y) / sqrt 2) the mid-surface curve is (s, z) through the
mid-points m = (b + t) / 2, n its unit normal from the neighbouring mid-points, thickness
h = |(t - b) . n| (as the shell measures thickness, and as 08's post.py), eps_thickness =
ln(h / h0), which includes the elastic part. punch_gap_mm: distance of the lower face node from
the punch sphere (negative: penetration; ~0: in contact). Python 3 standard library only.
"""
import argparse
import csv
import math
import os
import re

import from08

R_PUNCH = 50.8  # data/scenes/ex4b_square_clamped.toml
LINES = {"LINEX": "x", "LINEY": "y", "LINED": "diagonal"}


def parse_deck(path):
    nodes, sets, travel_end, h0, outputs = {}, {}, None, None, None
    mode = None
    with open(path) as f:
        for ln in f.read().splitlines():
            m = re.match(r"\*\* punch travel (\S+) -> (\S+) mm", ln)
            if m:
                travel_end = float(m.group(2))
                continue
            m = re.match(r"\*\* output travels (.*)", ln)
            if m:
                outputs = [float(x) for x in m.group(1).split()]
                continue
            m = re.match(r"\*\* case .* thickness (\S+) mm", ln)
            if m:
                h0 = float(m.group(1))
            if ln.startswith("*"):
                up = ln.upper().replace(" ", "")
                mode = None
                if up.startswith("*NODE,NSET=NALL"):
                    mode = "node"
                for s in LINES:
                    if up == f"*NSET,NSET={s}":
                        mode = s
                        sets[s] = []
                continue
            if mode == "node":
                p = ln.split(",")
                nodes[int(p[0])] = tuple(float(x) for x in p[1:4])
            elif mode in LINES:
                sets[mode] += [int(x) for x in ln.split(",") if x.strip()]
    return nodes, sets, travel_end, h0, outputs


# 08's .dat reader (the same ccx output blocks).
parse_dat = from08.load("post").parse_dat


def line_coord(line, x, y):
    return {"x": x, "y": y, "diagonal": (x + y) / math.sqrt(2.0)}[line]


def line_profile(nodes, cols, line, h0, U0, U1, wgt, T):
    """The through-thickness lines of one symmetry line at travel T, the displacements interpolated
    as U0 + wgt (U1 - U0) (U0 None: the undeformed start). One tuple per line, from the centre:
    (x0, y0, r0, s, z, h, eps_thickness, punch_gap, (s, z) of the lower face node, of the upper)."""

    def pos(i):
        u0 = U0[i] if U0 is not None else (0.0, 0.0, 0.0)
        u = [u0[c] + wgt * (U1[i][c] - u0[c]) for c in range(3)]
        x = nodes[i]
        return (line_coord(line, x[0] + u[0], x[1] + u[1]), x[2] + u[2])

    # punch sphere centre at travel T, in the line's (s, z) plane (it is on the axis)
    zc = -0.5 * h0 - R_PUNCH + T
    mids = []
    for b, t in cols:
        pb, pt = pos(b), pos(t)
        mids.append(((pb[0] + pt[0]) / 2, (pb[1] + pt[1]) / 2, pb, pt))
    out = []
    for q, (ms, mz, pb, pt) in enumerate(mids):
        lo, hi = max(0, q - 1), min(len(mids) - 1, q + 1)
        ts, tz = mids[hi][0] - mids[lo][0], mids[hi][1] - mids[lo][1]
        tn = math.hypot(ts, tz)
        ns, nz = -tz / tn, ts / tn
        h = abs((pt[0] - pb[0]) * ns + (pt[1] - pb[1]) * nz)
        x0, y0 = nodes[cols[q][0]][0], nodes[cols[q][0]][1]
        out.append((x0, y0, math.hypot(x0, y0), ms, mz, h, math.log(h / h0),
                    math.hypot(pb[0], pb[1] - zc) - R_PUNCH, pb, pt))
    return out


def interp_r0(prof, r0, k):
    """Column k of a profile, interpolated linearly in r0."""
    for a, b in zip(prof, prof[1:]):
        if a[2] - 1e-9 <= r0 <= b[2] + 1e-9:
            t = (r0 - a[2]) / (b[2] - a[2])
            return a[k] + t * (b[k] - a[k])
    return float("nan")


def chord_strain(pts0, pts):
    """ln(polyline length now / at the start) of the points (s, z)."""
    length = lambda p: sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(p, p[1:]))
    return math.log(length(pts) / length(pts0))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("deck")
    p.add_argument("dat")
    p.add_argument("-o", "--out", required=True)
    p.add_argument("--early-travels", default="0.5,1,2,3",
                   help="extra output travels [mm] besides the deck's (comma-separated; '' none)")
    a = p.parse_args()
    nodes, sets, T_end, h0, outputs = parse_deck(a.deck)
    blocks = parse_dat(a.dat)
    os.makedirs(a.out, exist_ok=True)

    forces = {}
    with open(os.path.join(a.out, "load_travel.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["punch_travel_mm", "punch_force_N"])
        w.writerow(["0", "0"])
        for kind, _, time, rows in blocks:
            if kind == "total force":
                w.writerow([f"{time * T_end:.5f}", f"{4.0 * rows[0][2]:.3f}"])
                forces[time] = 4.0 * rows[0][2]

    early = [float(t) for t in a.early_travels.split(",") if t.strip()]
    final = outputs[-1]
    for sname, line in LINES.items():
        ids = sets[sname]
        cols = [(ids[2 * k], ids[2 * k + 1]) for k in range(len(ids) // 2)]
        incs = [(0.0, None)] + [(time * T_end, {int(r[0]): r[1:4] for r in rows})
                                for kind, s, time, rows in blocks
                                if kind == "displacements" and s == sname]
        last = incs[-1][0]
        outs = sorted(set(outputs) | {t for t in early if t < final})
        if 0.0 < last < final - 1e-6:  # the run stopped early: also its last state
            outs.append(last)
        for T in outs:
            hit = [k for k in range(1, len(incs)) if incs[k - 1][0] <= T + 1e-9 <= incs[k][0] + 2e-9]
            if not hit:
                continue
            (t0, U0), (t1, U1) = incs[hit[0] - 1], incs[hit[0]]
            wgt = 1.0 if t1 - t0 < 1e-12 else (T - t0) / (t1 - t0)
            stopped = T == last and T not in outputs and T not in early
            fname = (f"strains_travel_final_{line}.csv" if stopped
                     else f"strains_travel_{T:g}mm_{line}.csv")
            with open(os.path.join(a.out, fname), "w", newline="") as f:
                w = csv.writer(f)
                if stopped:
                    f.write(f"# punch_travel_mm={T:.4f} (the run stopped here)\n")
                w.writerow(["x0_mm", "y0_mm", "r0_mm", "r_mm", "z_mm", "thickness_mm",
                            "eps_thickness", "punch_gap_mm"])
                for x0, y0, _, ms, mz, h, e3, gap, _, _ in line_profile(
                        nodes, cols, line, h0, U0, U1, wgt, T):
                    w.writerow([f"{x0:.4f}", f"{y0:.4f}", f"{math.hypot(x0, y0):.4f}",
                                f"{ms:.4f}", f"{mz:.4f}", f"{h:.6f}", f"{e3:.6f}",
                                f"{gap:.5f}"])
        if line == "x":
            write_history(os.path.join(a.out, "history_x.csv"), nodes, cols, h0, incs, T_end,
                          forces)


HISTORY_R0 = (0.0, 2.5, 5.0, 10.0, 15.0)  # thickness strain history at these r0 [mm] along x


def write_history(path, nodes, cols, h0, incs, T_end, forces):
    """Along x at every converged increment: the force, the punch gap of the centre's lower-face
    node, the contact zone (the smallest and largest r0 whose lower-face node is within 0.005 mm
    of the punch: the contact can be a ring, the centre lifted off), the thickness strain at
    HISTORY_R0, and the in-plane (x) log strain of the first element's lower face, upper face and
    mid-surface (the polyline through its 3 node columns, 0 <= r0 <= one element)."""
    start = line_profile(nodes, cols, "x", h0, None, incs[1][1], 0.0, 0.0)
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["punch_travel_mm", "punch_force_N", "punch_gap_centre_mm", "contact_r0_min_mm",
                    "contact_r0_max_mm"]
                   + [f"eps_thickness_r0_{r:g}mm" for r in HISTORY_R0]
                   + ["eps_x_lower_el1", "eps_x_mid_el1", "eps_x_upper_el1"])
        for T, U in incs[1:]:
            prof = line_profile(nodes, cols, "x", h0, None, U, 1.0, T)
            touching = [q[2] for q in prof if q[7] <= 0.005] or [float("nan")]
            el = slice(0, 3)
            lower = chord_strain([q[8] for q in start[el]], [q[8] for q in prof[el]])
            upper = chord_strain([q[9] for q in start[el]], [q[9] for q in prof[el]])
            mid = chord_strain([(q[3], q[4]) for q in start[el]], [(q[3], q[4]) for q in prof[el]])
            F = forces.get(min(forces, key=lambda t: abs(t * T_end - T)), float("nan"))
            w.writerow([f"{T:.5f}", f"{F:.3f}", f"{prof[0][7]:.5f}", f"{min(touching):.4f}",
                        f"{max(touching):.4f}"]
                       + [f"{interp_r0(prof, r, 6):.6f}" for r in HISTORY_R0]
                       + [f"{lower:.6f}", f"{mid:.6f}", f"{upper:.6f}"])


if __name__ == "__main__":
    main()
