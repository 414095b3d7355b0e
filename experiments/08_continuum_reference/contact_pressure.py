#!/usr/bin/env python3
"""Contact pressure on the hemispherical punch of a CalculiX run with per-node punch reactions.

  contact_pressure.py DECK.inp RUN.dat TRAVEL_MM [--radius 50.8] [--thickness 0.85]
                      [--final-travel T]

The deck's punch is one layer of quadratic elements whose every node moves with the punch
(gen_deck.py); with `*NODE PRINT, NSET=PUNCH, TOTALS=YES` the .dat holds each punch node's
reaction. The layer is rigid, so a surface node's reaction is the contact force on it. Per tool
element on the punch surface (corner, mid-side, corner nodes) the pressure is
(F_a / k_a + F_m + F_c / k_c) / (2 pi r_m ds), with k the number of surface faces sharing a corner
and the forces along the surface normal, times 180 (ccx
reports axisymmetric reactions for a 2-degree sector: README section 1). Prints CSV:
phi_deg (angle from the punch axis), r_mm (radius of the element's mid-side node on the punch
surface), p_MPa (compressive positive), at the increment nearest TRAVEL_MM. The sheet's pole node,
which is in the punch node set (README section 1), is not on the punch surface and is skipped.
Python 3 standard library only.
"""
import argparse
import math
import re
import sys


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("deck")
    ap.add_argument("dat")
    ap.add_argument("travel", type=float)
    ap.add_argument("--radius", type=float, default=50.8)
    ap.add_argument("--thickness", type=float, default=0.85)
    ap.add_argument("--final-travel", type=float, default=None,
                    help="the deck's final travel (default: read from its '** punch travel' line)")
    a = ap.parse_args()
    nodes, tools, T_end, section = {}, [], a.final_travel, None
    for line in open(a.deck):
        m = re.match(r"\*\* punch travel 0 -> (\S+) mm", line)
        if m and T_end is None:
            T_end = float(m.group(1))
        if line.startswith("*"):
            head = line.upper().replace(" ", "")
            section = ("node" if head.startswith("*NODE,") else
                       "tool" if head.startswith("*ELEMENT,") and "ELSET=TOOLS" in head else None)
            continue
        p = line.replace(",", " ").split()
        if section == "node" and len(p) >= 3:
            nodes[int(p[0])] = (float(p[1]), float(p[2]))
        elif section == "tool" and len(p) == 9:
            tools.append([int(q) for q in p[1:]])
    if T_end is None:
        sys.exit(f"{a.deck}: no '** punch travel 0 -> T mm' line; give --final-travel")
    blocks, cur = [], None
    for line in open(a.dat):
        m = re.search(r"^\s*forces \(fx,fy,fz\) for set PUNCH and time\s+(\S+)", line)
        if m:
            cur = {}
            blocks.append((float(m.group(1)) * T_end, cur))
            continue
        p = line.split()
        if cur is not None and len(p) == 4 and p[0].isdigit():
            cur[int(p[0])] = (float(p[1]), float(p[2]))
        elif cur is not None and line.strip() and not p[0].isdigit():
            cur = None
    if not blocks:
        sys.exit(f"{a.dat}: no per-node punch forces (the deck needs TOTALS=YES on the PUNCH print)")
    travel, forces = min(blocks, key=lambda b: abs(b[0] - a.travel))
    R, zc = a.radius, -0.5 * a.thickness - a.radius  # punch centre at travel 0 (mm)

    def on_surface(n):
        x, y = nodes[n]
        return abs(math.hypot(x, y - zc) - R) < 1e-3

    def normal_force(n):  # the sheet's push on the punch along the surface normal
        x, y = nodes[n]
        d = math.hypot(x, y - zc)
        fx, fy = forces.get(n, (0.0, 0.0))
        return (fx * x / d + fy * (y - zc) / d) * 180.0

    shared = {}
    faces = []
    for el in tools:  # CAX8: corners 1-4, mid-sides 5-8; faces (1,2,5), (2,3,6), (3,4,7), (4,1,8)
        for c0, c1, m in ((0, 1, 4), (1, 2, 5), (2, 3, 6), (3, 0, 7)):
            f = (el[c0], el[m], el[c1])
            if all(on_surface(n) for n in f):
                faces.append(f)
                for n in (f[0], f[2]):
                    shared[n] = shared.get(n, 0) + 1
    def phi(n):  # angle from the punch axis
        return math.atan2(nodes[n][0], nodes[n][1] - zc)

    rows = []
    for a0, m, a1 in faces:
        xm = nodes[m][0]
        if xm <= 0.0:
            continue
        ds = abs(phi(a1) - phi(a0)) * R
        f = normal_force(a0) / shared[a0] + normal_force(m) + normal_force(a1) / shared[a1]
        rows.append((math.degrees(phi(m)), xm, f / (2.0 * math.pi * xm * ds)))
    rows.sort()
    print(f"# punch travel {travel:.4f} mm (the increment nearest {a.travel:g} mm)")
    print("phi_deg,r_mm,p_MPa")
    for phi_deg, r, p in rows:
        print(f"{phi_deg:.3f},{r:.4f},{p:.4f}")

if __name__ == "__main__":
    main()
