#!/usr/bin/env python3
"""Read a CalculiX .dat written by a gen_deck.py deck and write the result CSVs.

  <out>/load_travel.csv              punch_travel_mm, punch_force_N (every converged increment)
  <out>/strains_travel_<T>mm.csv     r0_mm, r_mm, z_mm, thickness_mm, eps_meridional,
                                     eps_circumferential, eps_thickness at the output travels
                                     (the last increment of each step)
  <out>/strains_travel_final.csv     the same at the last converged increment, if the run stopped
                                     before its final travel (travel in a comment line)

Punch travel: the deck ramps the punch displacement linearly within each step; step k ends at
total time k, so travel = T_{k-1} + (time - (k - 1)) (T_k - T_{k-1}). The step travels and the
output travels are read from the deck (its "punch travel a -> b mm" and "output travels"
comments). The strains at an output travel come from the face-node displacements interpolated
linearly between the two increments around it (increments <= 0.25 mm by default). The punch force is 180 x the summed
reaction of the punch nodes (CalculiX reports axisymmetric reactions for its 2-degree segment;
checked on a ring under a uniform pressure, README).

Thickness at a through-thickness material line of initial radius r0: the lower and upper face
nodes of that line, b and t; the mid-point m = (b + t) / 2; n the unit normal of the mid-surface
curve through the m of the neighbouring lines; thickness = |(t - b) . n| (the shell measures
thickness normal to its mid-surface); eps_thickness = ln(thickness / h0). r_mm, z_mm are the
mid-point coordinates. eps_meridional = ln(mid-surface chord between the neighbouring lines /
its initial length), eps_circumferential = ln(r / r0) (at the axis: = eps_meridional). Python 3 standard library only.
"""
import argparse
import csv
import math
import os
import re


def parse_deck(path):
    nodes, faces_ids, travels, h0, outputs = {}, [], [], None, None
    with open(path) as f:
        lines = f.read().splitlines()
    k = 0
    mode = None
    for ln in lines:
        m = re.match(r"\*\* punch travel (\S+) -> (\S+) mm", ln)
        if m:
            travels.append((float(m.group(1)), float(m.group(2))))
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
            mode = "node" if up.startswith("*NODE,NSET=NALL") else (
                "faces" if up.startswith("*NSET,NSET=FACES") else None)
            continue
        if mode == "node":
            p = ln.split(",")
            nodes[int(p[0])] = (float(p[1]), float(p[2]))
        elif mode == "faces":
            faces_ids += [int(x) for x in ln.split(",") if x.strip()]
    if outputs is None:  # one step per output travel (older decks): the step ends
        outputs = [b for _, b in travels]
    return nodes, faces_ids, travels, h0, outputs


def parse_dat(path):
    """Blocks: list of (kind, set, time, rows)."""
    blocks = []
    cur = None
    with open(path) as f:
        for ln in f:
            m = re.match(r"\s*(total force|displacements) \(.*\) for set (\S+) and time\s+(\S+)",
                         ln)
            if m:
                cur = (m.group(1), m.group(2), float(m.group(3)), [])
                blocks.append(cur)
                continue
            if cur is not None and ln.strip():
                try:
                    cur[3].append([float(x) for x in ln.split()])
                except ValueError:
                    cur = None
    return blocks


def travel_of(time, travels):
    k = min(len(travels), max(1, math.ceil(time - 1e-9)))
    a, b = travels[k - 1]
    return a + (time - (k - 1)) * (b - a)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("deck")
    p.add_argument("dat")
    p.add_argument("-o", "--out", required=True)
    a = p.parse_args()
    nodes, faces, travels, h0, outputs = parse_deck(a.deck)
    blocks = parse_dat(a.dat)
    os.makedirs(a.out, exist_ok=True)

    with open(os.path.join(a.out, "load_travel.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["punch_travel_mm", "punch_force_N"])
        w.writerow(["0", "0"])
        for kind, _, time, rows in blocks:
            if kind == "total force":
                w.writerow([f"{travel_of(time, travels):.5f}", f"{180.0 * rows[0][1]:.3f}"])

    # face nodes come in pairs per column: ids were listed as (i, j=0), (i, j=2nl) for each i
    cols = [(faces[2 * k], faces[2 * k + 1]) for k in range(len(faces) // 2)]
    incs = [(travel_of(time, travels), {int(r[0]): (r[1], r[2]) for r in rows})
            for kind, _, time, rows in blocks if kind == "displacements"]
    incs = [(0.0, None)] + incs
    last = incs[-1][0] if len(incs) > 1 else 0.0
    if last < outputs[-1] - 1e-6 and last > 0.0:  # the run stopped early: also its last state
        outputs = outputs + [last]
    for T in outputs:
        hit = [k for k in range(1, len(incs)) if incs[k - 1][0] <= T + 1e-9 <= incs[k][0] + 2e-9]
        if not hit:
            continue
        k = hit[0]
        (t0, U0), (t1, U1) = incs[k - 1], incs[k]
        wgt = 1.0 if t1 - t0 < 1e-12 else (T - t0) / (t1 - t0)
        def disp(i):
            u1 = U1[i]
            u0 = U0[i] if U0 is not None else (0.0, 0.0)
            return (u0[0] + wgt * (u1[0] - u0[0]), u0[1] + wgt * (u1[1] - u0[1]))
        pos = lambda i: (nodes[i][0] + disp(i)[0], nodes[i][1] + disp(i)[1])
        mids = []
        for b, t in cols:
            pb, pt = pos(b), pos(t)
            mids.append(((pb[0] + pt[0]) / 2, (pb[1] + pt[1]) / 2, pb, pt))
        early = T == last and T not in outputs[:-1] and last < travels[-1][1] - 1e-6
        fname = "strains_travel_final.csv" if early else f"strains_travel_{T:g}mm.csv"
        with open(os.path.join(a.out, fname), "w", newline="") as f:
            w = csv.writer(f)
            if early:
                f.write(f"# punch_travel_mm={T:.4f} (the run stopped here)\n")
            w.writerow(["r0_mm", "r_mm", "z_mm", "thickness_mm", "eps_meridional",
                        "eps_circumferential", "eps_thickness"])
            for q, (mx, mz, pb, pt) in enumerate(mids):
                lo, hi = max(0, q - 1), min(len(mids) - 1, q + 1)
                tx, tz = mids[hi][0] - mids[lo][0], mids[hi][1] - mids[lo][1]
                tn = math.hypot(tx, tz)
                nx, nz = -tz / tn, tx / tn
                h = abs((pt[0] - pb[0]) * nx + (pt[1] - pb[1]) * nz)
                r0 = nodes[cols[q][0]][0]
                # meridional: mid-surface arc length between the neighbouring lines
                ds0 = nodes[cols[hi][0]][0] - nodes[cols[lo][0]][0]
                e1 = math.log(tn / ds0)
                e2 = math.log(mx / r0) if r0 > 0.0 else e1
                w.writerow([f"{r0:.4f}", f"{mx:.4f}", f"{mz:.4f}", f"{h:.6f}", f"{e1:.6f}",
                            f"{e2:.6f}", f"{math.log(h / h0):.6f}"])


if __name__ == "__main__":
    main()
