#!/usr/bin/env python3
"""Write a CalculiX (ccx 2.20) input deck: a 3D continuum twin of ex4b (square blank, clamped
edges, hemispherical punch, sticking contact), quarter model.

Scene: data/scenes/ex4b_square_clamped.toml. Units and conventions as in
forward/contact/rigid_tool.cc and experiments/08_continuum_reference: mm, N, MPa; the sheet
mid-surface starts at z = 0; the punch moves +z from below and its apex touches the lower sheet
face at travel 0. Quarter x, y >= 0 with symmetry planes x = 0 and y = 0.

* Sheet: 20-node quadratic bricks (C3D20R by default), `divisions` x `divisions` equal elements
  in plane on the quarter square [0, a]^2 (a = 59.18 mm, the half side) and `layers` through the
  thickness.
* Clamped edges x = a and y = a: every node of the edge faces (all through-thickness nodes) has
  zero displacement: the material line through the thickness at the edge neither moves nor
  rotates, which is the shell's clamp (mid-surface fixed, director kept vertical); see README.
* Punch: rigid, as in 08: one layer (1 mm deep, radially inwards) of C3D20 elements behind the
  spherical surface, every node with the prescribed displacement (travel along +z); the punch
  force is the sum of the reactions of the punch nodes, times 4 for the whole blank (post.py).
  The surface is the part of the quarter cap above the plan square [0, 35 mm]^2 (the contact
  reaches about 20-25 mm at 20 mm of travel; post.py's punch_gap_mm shows it), a plan grid lifted
  onto the sphere, all nodes (midsides too) on it.
* Contact: face-to-face penalty (SURFACE TO SURFACE, as in 08), slave = sheet lower face, master
  = punch surface; linear pressure-overclosure 5e4 MPa/mm; "sticking" = Coulomb friction with a
  large coefficient (`--friction`, 1.0 by default) and a stick slope of 5e3 MPa/mm.
* Material: E 210 GPa, nu 0.3 (as 08 for the ex1 steel), von Mises, Swift hardening as a
  *PLASTIC table, NLGEOM, rate-independent.
* One static step, punch ramped to the final travel; reactions of the punch and displacements of
  the face nodes along x (y = 0), y (x = 0) and the diagonal at every increment.

Usage: gen_deck.py --divisions 8 --layers 2 -o runs/NAME/NAME.inp
Python 3 standard library only.
"""
import argparse
import math
import sys

import from08

# data/scenes/ex4b_square_clamped.toml (+ elasticity of the ex1 steel, see 08's README)
SCENE = dict(half_side=59.18, thickness=0.85, K=589.0, eps0=0.0032, n=0.216,
             E=210000.0, nu=0.3, punch_radius=50.8, travels=[5, 10, 15, 20])


# 08's Swift *PLASTIC table (dense where the curve bends: linear interpolation error < 0.05 %
# of the stress) and node-set writer.
_gen08 = from08.load("gen_deck")
swift_table, fmt_set = _gen08.swift_table, _gen08.fmt_set


class Deck:
    def __init__(self):
        self.nodes = {}
        self.elems = {}

    def node(self, x):
        i = len(self.nodes) + 1
        self.nodes[i] = x
        return i

    def elem(self, conn):
        i = len(self.elems) + 1
        self.elems[i] = conn
        return i


def brick(g, i, j, k):
    """C3D20 connectivity of the brick with lowest corner (i, j, k) of a node grid g (indices
    step 2 per element): corners 1-4 at k (counter-clockwise seen from +z), 5-8 at k + 2, then
    midsides of the lower face, the upper face and the vertical edges."""
    c = [(i, j), (i + 2, j), (i + 2, j + 2), (i, j + 2)]
    m = [(i + 1, j), (i + 2, j + 1), (i + 1, j + 2), (i, j + 1)]
    return ([g[p + (k,)] for p in c] + [g[p + (k + 2,)] for p in c] +
            [g[p + (k,)] for p in m] + [g[p + (k + 2,)] for p in m] +
            [g[p + (k + 1,)] for p in c])


def is_node(i, j, k):
    return (i % 2) + (j % 2) + (k % 2) <= 1


def write_deck(a, out):
    sc = SCENE
    h0, L, R = sc["thickness"], sc["half_side"], sc["punch_radius"]
    n, nl = a.divisions, a.layers
    travels = [x for x in sc["travels"] if x <= a.travel + 1e-9]
    if not travels or travels[-1] < a.travel - 1e-9:
        travels.append(a.travel)
    d = Deck()

    # ---- sheet: node (i, j, k), i, j = 0..2n in plane, k = 0..2nl through the thickness
    g = {}
    for k in range(2 * nl + 1):
        for j in range(2 * n + 1):
            for i in range(2 * n + 1):
                if is_node(i, j, k):
                    g[i, j, k] = d.node((L * i / (2 * n), L * j / (2 * n),
                                         -0.5 * h0 + h0 * k / (2 * nl)))
    sheet_el = {}
    for l in range(nl):
        for ej in range(n):
            for ei in range(n):
                sheet_el[ei, ej, l] = d.elem(brick(g, 2 * ei, 2 * ej, 2 * l))

    # ---- punch: surface grid (p, q) = 0..2m on [0, 1]^2, mapped to the plan square [0, rp]^2
    # ("cartesian", default) or to the quarter disc of radius rp by the concentric map (the
    # square of side s goes to the circle of radius s rp), then lifted onto the sphere; the inner
    # layer lies 1 mm deeper along the sphere's radius. The concentric map distorts the faces
    # near the pole, whose quadratic interpolation then misses the sphere by ~0.002 mm there (the
    # sphere is quadratic in x, y, not in the face coordinates): contact chatter at 7.5 mm
    # (README). The cartesian faces represent z = zc + sqrt(R^2 - x^2 - y^2) to O(x^4 / R^3).
    m, depth = a.punch_divisions, 1.0
    rp = a.punch_plan_size_mm
    zc = -0.5 * h0 - R  # sphere centre: the apex touches the lower face at travel 0

    def punch_point(u, v, k):
        if a.punch_map == "cartesian":
            x, y = rp * u, rp * v
        else:
            s = max(u, v)
            f = 0.0 if s == 0.0 else rp * s / math.hypot(u, v)
            x, y = f * u, f * v
        z = zc + math.sqrt(R * R - x * x - y * y)
        rad = R - depth * (2 - k) / 2.0  # k = 2: surface, k = 0: 1 mm inside
        return (x * rad / R, y * rad / R, zc + (z - zc) * rad / R)

    pg = {}
    for k in range(3):
        for q in range(2 * m + 1):
            for p in range(2 * m + 1):
                if is_node(p, q, k):
                    pg[p, q, k] = d.node(punch_point(p / (2 * m), q / (2 * m), k))
    punch_el = [d.elem(brick(pg, 2 * p, 2 * q, 0)) for q in range(m) for p in range(m)]
    punch_nodes = sorted(pg.values())

    w = out.write
    w(f"** generated by gen_deck.py {' '.join(sys.argv[1:])}\n")
    w(f"** case ex4b: half side {L} mm, thickness {h0} mm, {n} x {n} x {nl} {a.element}, "
      f"punch friction {a.friction}, E {sc['E']} MPa\n")
    w("*NODE, NSET=NALL\n")
    for i, (x, y, z) in d.nodes.items():
        w(f"{i}, {x:.9f}, {y:.9f}, {z:.9f}\n")
    w(f"*ELEMENT, TYPE={a.element}, ELSET=SHEET\n")
    for e in sorted(sheet_el.values()):
        w(f"{e}, " + ", ".join(map(str, d.elems[e][:15])) + ",\n"
          + ", ".join(map(str, d.elems[e][15:])) + "\n")
    w("*ELEMENT, TYPE=C3D20, ELSET=PUNCHEL\n")
    for e in punch_el:
        w(f"{e}, " + ", ".join(map(str, d.elems[e][:15])) + ",\n"
          + ", ".join(map(str, d.elems[e][15:])) + "\n")

    top = 2 * nl
    w("*NSET, NSET=PUNCH\n" + fmt_set(punch_nodes) + "\n")
    w("*NSET, NSET=SYMX\n" + fmt_set(v for (i, j, k), v in sorted(g.items()) if i == 0) + "\n")
    w("*NSET, NSET=SYMY\n" + fmt_set(v for (i, j, k), v in sorted(g.items()) if j == 0) + "\n")
    w("*NSET, NSET=CLAMP\n" + fmt_set(v for (i, j, k), v in sorted(g.items())
                                      if i == 2 * n or j == 2 * n) + "\n")
    # lines for the thickness: pairs (lower face node, upper face node), in order from the centre
    w("*NSET, NSET=LINEX\n" + fmt_set(x for i in range(2 * n + 1)
                                      for x in (g[i, 0, 0], g[i, 0, top])) + "\n")
    w("*NSET, NSET=LINEY\n" + fmt_set(x for j in range(2 * n + 1)
                                      for x in (g[0, j, 0], g[0, j, top])) + "\n")
    w("*NSET, NSET=LINED\n" + fmt_set(x for i in range(0, 2 * n + 1, 2)
                                      for x in (g[i, i, 0], g[i, i, top])) + "\n")
    w("*ELSET, ELSET=SHEETBOT\n" + fmt_set(sheet_el[ei, ej, 0] for ej in range(n)
                                           for ei in range(n)) + "\n")
    # sheet lower face: S1 (nodes 1-4) of the bottom layer; punch surface: S2 (nodes 5-8)
    w("*SURFACE, NAME=SBOT\nSHEETBOT, S1\n*SURFACE, NAME=MPUNCH\nPUNCHEL, S2\n")

    w("*MATERIAL, NAME=SHEETMAT\n*ELASTIC\n" + f"{sc['E']}, {sc['nu']}\n*PLASTIC\n")
    for s, e in swift_table(sc["K"], sc["eps0"], sc["n"]):
        w(f"{s:.6f}, {e:.8f}\n")
    w("*MATERIAL, NAME=TOOLMAT\n*ELASTIC\n" + f"{sc['E']}, 0.3\n")
    w("*SOLID SECTION, ELSET=SHEET, MATERIAL=SHEETMAT\n")
    w("*SOLID SECTION, ELSET=PUNCHEL, MATERIAL=TOOLMAT\n")

    w("*CONTACT PAIR, INTERACTION=IPUNCH, TYPE=SURFACE TO SURFACE\nSBOT, MPUNCH\n")
    w("*SURFACE INTERACTION, NAME=IPUNCH\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n"
      f"{a.penalty}\n")
    if a.friction > 0.0:
        w(f"*FRICTION\n{a.friction}, {a.stick_slope}\n")

    w("*BOUNDARY\nSYMX, 1, 1, 0.\nSYMY, 2, 2, 0.\nCLAMP, 1, 3, 0.\nPUNCH, 1, 2, 0.\n"
      "PUNCH, 3, 3, 0.\n")

    T_end = travels[-1]
    w(f"** punch travel 0 -> {T_end:g} mm\n")
    w("** output travels " + " ".join(f"{T:g}" for T in travels) + "\n")
    dt0 = min(1.0, a.first_increment_mm / T_end)
    dtmax = min(1.0, a.max_increment_mm / T_end)
    w(f"*STEP, NLGEOM, INC={a.max_increments}\n*STATIC\n{dt0:.6g}, 1.0, {1e-7:.6g}, "
      f"{dtmax:.6g}\n")
    w("*CONTROLS, PARAMETERS=TIME INCREMENTATION\n" f"{a.controls}\n")
    w(f"*BOUNDARY\nPUNCH, 3, 3, {T_end:.6f}\n")
    w("*NODE PRINT, NSET=PUNCH, TOTALS=ONLY\nRF\n")
    for s in ("LINEX", "LINEY", "LINED"):
        w(f"*NODE PRINT, NSET={s}\nU\n")
    if a.frd:
        w("*NODE FILE, FREQUENCY=20\nU\n*EL FILE, FREQUENCY=20\nPEEQ\n*CONTACT FILE, "
          "FREQUENCY=20\nCDIS, CSTR\n")
    w("*END STEP\n")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--divisions", type=int, default=8, help="sheet elements per quarter side")
    p.add_argument("--layers", type=int, default=2, help="sheet elements through the thickness")
    p.add_argument("--element", default="C3D20R", choices=["C3D20R", "C3D20"])
    p.add_argument("--friction", type=float, default=1.0,
                   help="punch friction coefficient ('sticking': a large value)")
    p.add_argument("--punch-divisions", type=int, default=16,
                   help="punch surface elements per quarter side (concentric map)")
    p.add_argument("--punch-map", default="cartesian", choices=["cartesian", "concentric"])
    p.add_argument("--punch-plan-size-mm", type=float, default=35.0,
                   help="plan half side (cartesian) or radius (concentric) of the punch surface")
    p.add_argument("--travel", type=float, default=20.0, help="final punch travel [mm]")
    p.add_argument("--penalty", type=float, default=5.0e4,
                   help="contact penalty [MPa/mm] (08 used 2e5: diverged here, README)")
    p.add_argument("--stick-slope", type=float, default=5.0e3, help="friction stick slope [MPa/mm]")
    p.add_argument("--first-increment-mm", type=float, default=0.05)
    p.add_argument("--max-increment-mm", type=float, default=0.25)
    p.add_argument("--max-increments", type=int, default=2000)
    p.add_argument("--controls", default="8, 10, 9, 16, 10, 4, 0, 5",
                   help="*CONTROLS TIME INCREMENTATION line (I0, IR, IP, IC, IL, IG, IS, IA)")
    p.add_argument("--frd", action="store_true", help="also write U, PEEQ, contact to the .frd")
    p.add_argument("-o", "--output", required=True)
    a = p.parse_args()
    with open(a.output, "w") as f:
        write_deck(a, f)


if __name__ == "__main__":
    main()
