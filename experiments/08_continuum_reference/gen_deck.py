#!/usr/bin/env python3
"""Write a CalculiX (ccx 2.20) input deck: an axisymmetric continuum twin of a vshell scene.

The sheet is meshed with 8-node quadratic axisymmetric elements (CAX8R by default), `layers`
elements through the thickness and `radial` elements along the radius. Tools are rigid: one layer
of elements behind the tool surface whose every node has a prescribed displacement (the punch
moves +z by the travel, die and holder stay fixed); the punch force is the sum of the reactions of
the punch nodes. Contact is face-to-face penalty contact with Coulomb friction.

Geometry, units and conventions are those of forward/contact/rigid_tool.cc: mm, N, MPa; the
sheet mid-surface starts at z = 0; the punch moves +z from below and its apex (or flat face)
touches the lower sheet face at travel 0; the die is above the sheet, its shoulder torus tangent
to the die face z = h0/2 and to the opening wall r = die radius; a fixed-gap holder is a flat face
gap_mm below the die face. CalculiX axisymmetric coordinates: x = r, y = z.

Edge condition "pinned" (ex1): the shell's pinned rim node fixes the mid-surface position and
leaves the rotation free. In the solid this is the mean displacement of the rim section: two
*EQUATIONs make the thickness-weighted mean radial and mean axial displacement of the rim nodes
zero (weights of the quadratic edge interpolation: 1, 4, 2, 4, ..., 4, 1); the rim section may
rotate, stretch and warp. Edge "free" (ex3): nothing.

Usage: gen_deck.py --case ex1 --friction 0.1 --radial 120 --layers 4 -o decks/NAME.inp
       gen_deck.py --help
Python 3 standard library only.
"""
import argparse
import math
import sys

# ---- scenes (numbers copied from data/scenes/*.toml; see the README for the sources) ----
SCENES = {
    # data/scenes/ex1_hemispherical_stretching.toml (AK steel proxy: E = 210 GPa, nu = 0.3)
    "ex1": dict(blank_radius=59.18, thickness=0.85, edge="pinned",
                K=589.0, eps0=0.0032, n=0.216, E=210000.0, nu=0.3,
                punch=dict(kind="hemispherical", radius=50.8),
                die=dict(radius=52.83, profile=6.35), holder_gap=None,
                die_friction=0.04, travels=[5, 10, 15, 20, 25, 30]),
    # data/scenes/ex3_flat_punch_cup_fixed_gap.toml (AA6016-T4: E = 70 GPa, nu = 0.33), R = 1
    # here (the continuum is von Mises; vshell is run with --set material.r_value=1).
    "ex3": dict(blank_radius=53.75, thickness=1.0, edge="free",
                K=478.2, eps0=0.0068, n=0.2895, E=70000.0, nu=0.33,
                punch=dict(kind="flat", radius=30.0, profile=5.0),
                die=dict(radius=31.2, profile=10.0), holder_gap=1.04,
                die_friction=0.07, travels=[5, 10, 15, 20, 25, 30, 35, 40]),
}


# ---- tool profiles: primitives with the sheet-side normal (as in rigid_tool.cc) ----
def seg(p0, p1, normal):
    return ("seg", p0, p1, normal)


def arc(c, rho, a0, a1):
    """Convex arc (sheet outside the circle), counter-clockwise from a0 to a1 (radians)."""
    return ("arc", c, rho, a0, a1)


def prim_length(p):
    if p[0] == "seg":
        return math.dist(p[1], p[2])
    return p[2] * abs(p[4] - p[3])


def prim_point(p, s, reverse):
    """Point and sheet-side unit normal at parameter s in [0, 1]."""
    if reverse:
        s = 1.0 - s
    if p[0] == "seg":
        (x0, y0), (x1, y1) = p[1], p[2]
        return (x0 + s * (x1 - x0), y0 + s * (y1 - y0)), p[3]
    c, rho, a0, a1 = p[1], p[2], p[3], p[4]
    a = a0 + s * (a1 - a0)
    n = (math.cos(a), math.sin(a))
    return (c[0] + rho * n[0], c[1] + rho * n[1]), n


def sample_path(prims, h, first_mm=None):
    """Surface points (2 n + 1 along the path, corner/midside alternating) and normals.
    prims: list of (primitive, reverse) joined end to start. first_mm: length of the first
    element of the path (the rest uniform), for a path starting on the axis (see tool_profile)."""
    pts, nrm = [], []
    for k, (p, rev) in enumerate(prims):
        L = prim_length(p)
        if k == 0 and first_mm:
            ne = max(1, math.ceil((L - first_mm) / h))
            s_c = [0.0] + [first_mm / L + (1.0 - first_mm / L) * q / ne for q in range(ne + 1)]
        else:
            ne = max(1, math.ceil(L / h))
            s_c = [q / ne for q in range(ne + 1)]
        svals = []
        for q in range(len(s_c) - 1):
            svals += [s_c[q], 0.5 * (s_c[q] + s_c[q + 1])]
        svals.append(1.0)
        for q, sv in enumerate(svals):
            if k > 0 and q == 0:
                continue
            x, n = prim_point(p, sv, rev)
            pts.append(x)
            nrm.append(n)
    return pts, nrm


def tool_profile(scene, tool, t):
    """Primitives of one tool, ordered along the path, trimmed to where the sheet can touch."""
    h0 = scene["thickness"]
    pi = math.pi
    if tool == "punch" and scene["punch"]["kind"] == "hemispherical":
        R = scene["punch"]["radius"]
        c = (0.0, -0.5 * h0 - R)
        # from the apex down to 80 degrees (r = 50.0 mm: beyond the contact at 30 mm of travel)
        return [(arc(c, R, 0.5 * pi - math.radians(80.0), 0.5 * pi), True)]
    if tool == "punch":
        R, rho = scene["punch"]["radius"], scene["punch"]["profile"]
        top = -0.5 * h0
        return [(seg((0.0, top), (R - rho, top), (0.0, 1.0)), False),
                (arc((R - rho, top - rho), rho, 0.0, 0.5 * pi), True),
                (seg((R, top - rho), (R, top - rho - 40.0), (1.0, 0.0)), False)]
    if tool == "die":
        Ro, rho = scene["die"]["radius"], scene["die"]["profile"]
        face = 0.5 * h0
        prims = [(seg((Ro, face + rho + 15.0), (Ro, face + rho), (-1.0, 0.0)), False),
                 (arc((Ro + rho, face + rho), rho, pi, 1.5 * pi), False)]
        # the flat die face beyond the shoulder (as in rigid_tool.cc): the cup flange slides on
        # it; in ex1 the rim section rotates about its pinned mean and its upper corner moves
        # past the end of the shoulder arc (r = clamp radius), so the face must be there too
        prims.append((seg((Ro + rho, face), (scene["blank_radius"] + 4.0, face),
                          (0.0, -1.0)), False))
        return prims
    if tool == "holder":
        Ro, rho = scene["die"]["radius"], scene["die"]["profile"]
        top = 0.5 * h0 - scene["holder_gap"]
        return [(seg((Ro + rho, top), (scene["blank_radius"] + 4.0, top), (0.0, 1.0)), False)]
    raise ValueError(tool)


def swift_table(K, eps0, n, emax=2.0):
    """*PLASTIC table (true stress, equivalent plastic strain) of sigma = K (eps0 + eps_p)^n:
    dense where the curve bends (linear interpolation error < 0.05 % of the stress)."""
    eps = [0.0]
    e = 1e-4
    while e < emax:
        eps.append(e)
        e *= 1.12
    eps.append(emax)
    return [(K * (eps0 + x) ** n, x) for x in eps]


class Deck:
    def __init__(self):
        self.nodes = {}  # id -> (r, z)
        self.elems = {}  # id -> 8 node ids
        self.next_node = 1
        self.next_elem = 1

    def node(self, x):
        i = self.next_node
        self.nodes[i] = (max(0.0, x[0]), x[1])
        self.next_node += 1
        return i

    def elem(self, conn):
        i = self.next_elem
        self.elems[i] = conn
        self.next_elem += 1
        return i


def signed_area(p):
    return 0.5 * sum(p[k][0] * p[(k + 1) % 4][1] - p[(k + 1) % 4][0] * p[k][1] for k in range(4))


def mesh_tool(deck, prims, h, depth=1.0, first_mm=None):
    """One layer of CAX8 elements of `depth` behind the tool surface; face S1 is the surface.
    Returns (element ids, node ids)."""
    pts, nrm = sample_path(prims, h, first_mm)
    S = [deck.node(p) for p in pts]
    I = [deck.node((p[0] - depth * n[0], p[1] - depth * n[1])) for p, n in zip(pts, nrm)]
    M = {k: deck.node((pts[k][0] - 0.5 * depth * nrm[k][0], pts[k][1] - 0.5 * depth * nrm[k][1]))
         for k in range(0, len(pts), 2)}
    elems = []
    for k in range(0, len(pts) - 1, 2):
        conn = [S[k], S[k + 2], I[k + 2], I[k], S[k + 1], M[k + 2], I[k + 1], M[k]]
        if signed_area([deck.nodes[c] for c in conn[:4]]) < 0.0:
            conn = [S[k + 2], S[k], I[k], I[k + 2], S[k + 1], M[k], I[k + 1], M[k + 2]]
        elems.append(deck.elem(conn))
    return elems, S + I + list(M.values())


def fmt_set(ids, per_line=12):
    ids = list(ids)
    return "\n".join(", ".join(str(i) for i in ids[k:k + per_line]) + ","
                     for k in range(0, len(ids), per_line))


def write_deck(a, out):
    sc = dict(SCENES[a.case])
    if a.thickness is not None:
        sc["thickness"] = a.thickness
    if a.E is not None:
        sc["E"] = a.E
    if a.K is not None:
        sc["K"] = a.K
    if a.n is not None:
        sc["n"] = a.n
    h0, Rb = sc["thickness"], sc["blank_radius"]
    die_mu = sc["die_friction"] if a.die_friction is None else a.die_friction
    travels = [x for x in sc["travels"] if x <= a.travel + 1e-9]
    if not travels or travels[-1] < a.travel - 1e-9:
        travels.append(a.travel)
    d = Deck()

    # ---- sheet: node (i, j), i = 0..2 ne along r (uniform), j = 0..2 nl through the thickness
    ne, nl = a.radial, a.layers
    # radial element lengths: `radial` equal elements, except that the first one is replaced by
    # a geometric sequence (factor 1.5) from axis_element_mm up: the sheet face touching the
    # axis is a collapsed face in CalculiX's expansion, with ill-defined contact, so it is kept
    # tiny (README). Node positions: corners at the element ends, midsides halfway.
    h_u = Rb / ne
    lens = []
    x = a.axis_element_mm
    while x < h_u and a.axis_element_mm > 0.0:
        lens.append(x)
        x *= 1.5
    n_u = max(1, round((Rb - sum(lens)) / h_u))
    lens += [(Rb - sum(lens)) / n_u] * n_u
    ne = len(lens)
    corners = [0.0]
    for L in lens:
        corners.append(corners[-1] + L)
    def rpos(i):
        return corners[i // 2] if i % 2 == 0 else 0.5 * (corners[i // 2] + corners[i // 2 + 1])
    grid = {}
    for i in range(2 * ne + 1):
        for j in range(2 * nl + 1):
            if i % 2 == 1 and j % 2 == 1:
                continue
            grid[i, j] = d.node((rpos(i), -0.5 * h0 + h0 * j / (2 * nl)))
    sheet_el = {}
    for e in range(ne):
        for l in range(nl):
            i, j = 2 * e, 2 * l
            conn = [grid[i, j], grid[i + 2, j], grid[i + 2, j + 2], grid[i, j + 2],
                    grid[i + 1, j], grid[i + 2, j + 1], grid[i + 1, j + 2], grid[i, j + 1]]
            sheet_el[e, l] = d.elem(conn)
    sheet_nodes = sorted(grid.values())
    sheet_elems = sorted(sheet_el.values())

    # ---- tools
    h_tool = a.tool_element_mm
    # The punch surface starts on the axis. CalculiX expands an axisymmetric face with a node on
    # the axis into a collapsed quadrilateral whose normal is undefined, and contact against it
    # fails (0.01 mm penetration under the pole with a 0.5 mm first face). The first punch face
    # is therefore only `axis_face_mm` long: the sheet's integration points beyond it see
    # regular faces.
    punch_el, punch_nodes = mesh_tool(d, tool_profile(sc, "punch", h0), h_tool,
                                      first_mm=a.axis_face_mm)
    die_el, die_nodes = mesh_tool(d, tool_profile(sc, "die", h0), h_tool)
    holder_el, holder_nodes = ([], [])
    if sc["holder_gap"] is not None:
        holder_el, holder_nodes = mesh_tool(d, tool_profile(sc, "holder", h0), h_tool)

    w = out.write
    w(f"** generated by gen_deck.py {' '.join(sys.argv[1:])}\n")
    w(f"** case {a.case}: blank radius {Rb} mm, thickness {h0} mm, {ne} x {nl} {a.element}, "
      f"punch friction {a.friction}, die friction {die_mu}, E {sc['E']} MPa\n")
    w("*NODE, NSET=NALL\n")
    for i, (x, y) in d.nodes.items():
        w(f"{i}, {x:.9f}, {y:.9f}\n")
    w(f"*ELEMENT, TYPE={a.element}, ELSET=SHEET\n")
    for e in sheet_elems:
        w(f"{e}, " + ", ".join(map(str, d.elems[e])) + "\n")
    w("*ELEMENT, TYPE=CAX8, ELSET=TOOLS\n")
    for e in punch_el + die_el + holder_el:
        w(f"{e}, " + ", ".join(map(str, d.elems[e])) + "\n")
    # The sheet's lower pole node (on the axis) rides on the punch apex: it is in contact from
    # travel 0 on (ex1: the apex touches it; ex3: the flat face does), and CalculiX's contact is
    # defective on faces with a node on the axis (README). It is given the punch displacement,
    # i.e. put into the punch node set, whose reactions make the punch force.
    pin = a.pin_pole if a.pin_pole is not None else int(sc["punch"]["kind"] == "hemispherical")
    pole = [grid[0, 0]] if pin else []
    w("*NSET, NSET=PUNCH\n" + fmt_set(punch_nodes + pole) + "\n")
    w("*NSET, NSET=FIXEDTOOLS\n" + fmt_set(die_nodes + holder_nodes) + "\n")
    w("*NSET, NSET=AXIS\n" + fmt_set(grid[0, j] for j in range(2 * nl + 1)) + "\n")
    w("*NSET, NSET=FACES\n" + fmt_set(grid[i, j] for i in range(2 * ne + 1)
                                      for j in (0, 2 * nl)) + "\n")
    w("*ELSET, ELSET=SHEETBOT\n" + fmt_set(sheet_el[e, 0] for e in range(ne)) + "\n")
    w("*ELSET, ELSET=SHEETTOP\n" + fmt_set(sheet_el[e, nl - 1] for e in range(ne)) + "\n")
    # surfaces: sheet lower face (S1 of the bottom layer), upper face (S3 of the top layer);
    # the tool surface is S1 of its elements.
    w("*SURFACE, NAME=SBOT\nSHEETBOT, S1\n*SURFACE, NAME=STOP\nSHEETTOP, S3\n")
    w("*ELSET, ELSET=PUNCHEL\n" + fmt_set(punch_el) + "\n*SURFACE, NAME=MPUNCH\nPUNCHEL, S1\n")
    w("*ELSET, ELSET=DIEEL\n" + fmt_set(die_el) + "\n*SURFACE, NAME=MDIE\nDIEEL, S1\n")
    if holder_el:
        w("*ELSET, ELSET=HOLDEREL\n" + fmt_set(holder_el) + "\n*SURFACE, NAME=MHOLDER\n"
          "HOLDEREL, S1\n")

    # ---- material: elastic + *PLASTIC table of the scene's Swift law (rate-independent)
    w("*MATERIAL, NAME=SHEETMAT\n*ELASTIC\n" + f"{sc['E']}, {sc['nu']}\n*PLASTIC\n")
    for s, e in swift_table(sc["K"], sc["eps0"], sc["n"]):
        w(f"{s:.6f}, {e:.8f}\n")
    w("*MATERIAL, NAME=TOOLMAT\n*ELASTIC\n" + f"{sc['E']}, 0.3\n")
    w("*SOLID SECTION, ELSET=SHEET, MATERIAL=SHEETMAT\n")
    w("*SOLID SECTION, ELSET=TOOLS, MATERIAL=TOOLMAT\n")

    # ---- edge condition
    if sc["edge"] == "pinned":
        ie = 2 * ne
        col = [grid[ie, j] for j in range(2 * nl + 1)]
        wts = [1.0 if j in (0, 2 * nl) else (4.0 if j % 2 == 1 else 2.0)
               for j in range(2 * nl + 1)]
        # dependent DOF first: the middle node of the rim section
        order = [nl] + [j for j in range(2 * nl + 1) if j != nl]
        for dof in (1, 2):
            w(f"** mean {'radial' if dof == 1 else 'axial'} displacement of the rim section = 0\n")
            w(f"*EQUATION\n{len(col)}\n")
            terms = [f"{col[j]}, {dof}, {wts[j]:.1f}" for j in order]
            for k in range(0, len(terms), 4):
                w(", ".join(terms[k:k + 4]) + "\n")

    # ---- contact
    K = a.penalty
    lam = a.stick_slope

    def pair(name, slave, master, mu):
        w(f"*CONTACT PAIR, INTERACTION={name}, TYPE=SURFACE TO SURFACE\n{slave}, {master}\n")
        w(f"*SURFACE INTERACTION, NAME={name}\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n"
          f"{K}\n")
        if mu > 0.0:
            w(f"*FRICTION\n{mu}, {lam}\n")

    pair("IPUNCH", "SBOT", "MPUNCH", a.friction)
    pair("IDIE", "STOP", "MDIE", die_mu)
    if holder_el:
        pair("IHOLDER", "SBOT", "MHOLDER", die_mu)

    w("*BOUNDARY\nAXIS, 1, 1, 0.\nFIXEDTOOLS, 1, 2, 0.\nPUNCH, 1, 1, 0.\nPUNCH, 2, 2, 0.\n")

    # ---- one step: the punch displacement ramped linearly over the step time 0..1 to the final
    # travel; the .dat gets the punch reaction and the face-node displacements at every
    # increment; post.py interpolates the outputs at the output travels between increments.
    # (One step per output travel restarts the contact/friction state at each step start and
    # costs a failed first increment each time; *TIME POINTS cannot be combined with output at
    # every increment in ccx 2.20.)
    T_end = travels[-1]
    w(f"** punch travel 0 -> {T_end:g} mm\n")
    w("** output travels " + " ".join(f"{T:g}" for T in travels) + "\n")
    dt0 = min(1.0, a.first_increment_mm / T_end)
    dtmax = min(1.0, a.max_increment_mm / T_end)
    w(f"*STEP, NLGEOM, INC={a.max_increments}\n*STATIC\n{dt0:.6g}, 1.0, {1e-7:.6g}, "
      f"{dtmax:.6g}\n")
    w("*CONTROLS, PARAMETERS=TIME INCREMENTATION\n" f"{a.controls}\n")
    w(f"*BOUNDARY\nPUNCH, 2, 2, {T_end:.6f}\n")
    w("*NODE PRINT, NSET=PUNCH, TOTALS=ONLY\nRF\n")
    w("*NODE PRINT, NSET=FACES\nU\n")
    w("*END STEP\n")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--case", choices=sorted(SCENES), required=True)
    p.add_argument("--friction", type=float, required=True, help="punch friction coefficient")
    p.add_argument("--die-friction", type=float, default=None,
                   help="die (and holder) friction; default: the scene's value")
    p.add_argument("--radial", type=int, default=120, help="sheet elements along the radius")
    p.add_argument("--layers", type=int, default=4, help="sheet elements through the thickness")
    p.add_argument("--axis-element-mm", type=float, default=0.0,
                   help="length of the sheet element on the axis (0: uniform mesh)")
    p.add_argument("--element", default="CAX8R", choices=["CAX8R", "CAX8"])
    p.add_argument("--thickness", type=float, default=None, help="override the sheet thickness [mm]")
    p.add_argument("--E", type=float, default=None, help="override Young's modulus [MPa]")
    p.add_argument("--K", type=float, default=None, help="override the Swift K [MPa]")
    p.add_argument("--n", type=float, default=None, help="override the Swift exponent n")
    p.add_argument("--travel", type=float, default=30.0, help="final punch travel [mm]")
    p.add_argument("--tool-element-mm", type=float, default=0.5, help="tool surface element length")
    p.add_argument("--axis-face-mm", type=float, default=0.01,
                   help="length of the first punch face, the one touching the axis")
    p.add_argument("--pin-pole", type=int, default=None,
                   help="1: the sheet's lower pole node moves with the punch (see the deck); "
                        "default 1 for ex1 (hemispherical punch), 0 for ex3 (the cup bottom "
                        "lifts off the flat punch by 0.1-0.2 mm)")
    p.add_argument("--penalty", type=float, default=2.0e5, help="contact penalty [MPa/mm]")
    p.add_argument("--stick-slope", type=float, default=2.0e4, help="friction stick slope [MPa/mm]")
    p.add_argument("--first-increment-mm", type=float, default=0.05)
    p.add_argument("--max-increment-mm", type=float, default=0.25)
    p.add_argument("--max-increments", type=int, default=2000)
    p.add_argument("--controls", default="8, 10, 9, 16, 10, 4, 0, 5",
                   help="*CONTROLS TIME INCREMENTATION line (I0, IR, IP, IC, IL, IG, IS, IA)")
    p.add_argument("-o", "--output", required=True)
    a = p.parse_args()
    with open(a.output, "w") as f:
        write_deck(a, f)


if __name__ == "__main__":
    main()
