#!/usr/bin/env python3
"""Response surface of the earing cost in two parameters (issue 17): the cup is run on a grid of
(p, q) values, each run's final rim profile is compared with the measured profile as the
calibration does it (data kind cup_height_profile, shape_only: periodic piecewise-linear
interpolation at the measured angles, the best constant offset removed, cost = 1/2 sum of squared
(difference / sigma)), and a quadratic surface is fitted to the costs by least squares. Its
minimum is the estimate; the scatter of the costs about the surface is the forward model's noise
in the cost, and refits with one grid point left out show how far that noise moves the minimum.

  cost_surface.py SCENE OUT --p KEY v1,v2,.. --q KEY w1,w2,.. --measured FILE [--sigma 0.1]
                  [--jobs 2] [--set KEY=VALUE ...]

Runs `build/app/vshell run` (one OpenMP thread each, --jobs at a time); a grid point whose
OUT/p_<i>_q_<j>/cup_profile.csv exists is not run again. Writes OUT/cost_surface.csv and prints
the fit. Python 3 standard library only."""
import argparse
import bisect
import concurrent.futures
import csv
import math
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def read_profile(path):
    rows = [r for r in csv.reader(open(path)) if r and not r[0].startswith("#")]
    head = rows[0]
    a, h = head.index("angle_from_rd_deg"), head.index("cup_height_mm")
    pts = sorted((float(r[a]) % 360.0, float(r[h])) for r in rows[1:])
    return [p[0] for p in pts], [p[1] for p in pts]


def read_measured(path):
    out = []
    for line in open(path):
        parts = line.replace(",", " ").split()
        if len(parts) >= 2:
            try:
                out.append((float(parts[0]), float(parts[1])))
            except ValueError:
                continue
    return out


def periodic_interp(angles, heights, t):
    t %= 360.0
    xs = angles + [angles[0] + 360.0]
    ys = heights + [heights[0]]
    if t < xs[0]:
        t += 360.0
    k = max(1, min(len(xs) - 1, bisect.bisect_right(xs, t)))
    x0, x1, y0, y1 = xs[k - 1], xs[k], ys[k - 1], ys[k]
    return y0 + (y1 - y0) * (t - x0) / (x1 - x0)


def cost(profile, measured, sigma):
    angles, heights = profile
    sim = [periodic_interp(angles, heights, t) for t, _ in measured]
    offset = sum(m - s for s, (_, m) in zip(sim, measured)) / len(measured)
    return 0.5 * sum(((s + offset - m) / sigma) ** 2 for s, (_, m) in zip(sim, measured))


def solve(a, b):
    """Gaussian elimination with partial pivoting (small dense systems)."""
    n = len(b)
    m = [row[:] + [b[i]] for i, row in enumerate(a)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(m[r][c]))
        m[c], m[p] = m[p], m[c]
        for r in range(c + 1, n):
            f = m[r][c] / m[c][c]
            for k in range(c, n + 1):
                m[r][k] -= f * m[c][k]
    x = [0.0] * n
    for r in reversed(range(n)):
        x[r] = (m[r][n] - sum(m[r][k] * x[k] for k in range(r + 1, n))) / m[r][r]
    return x


def quadratic_fit(points):
    """c = a0 + a1 u + a2 v + a3 u^2 + a4 u v + a5 v^2 on centred, scaled u, v."""
    basis = lambda u, v: [1.0, u, v, u * u, u * v, v * v]
    ata = [[0.0] * 6 for _ in range(6)]
    atb = [0.0] * 6
    for u, v, c in points:
        f = basis(u, v)
        for i in range(6):
            atb[i] += f[i] * c
            for j in range(6):
                ata[i][j] += f[i] * f[j]
    coef = solve(ata, atb)
    resid = [c - sum(a * f for a, f in zip(coef, basis(u, v))) for u, v, c in points]
    return coef, resid


def minimum(coef):
    _, b1, b2, h11, h12, h22 = coef
    det = 4.0 * h11 * h22 - h12 * h12
    if h11 <= 0.0 or det <= 0.0:
        return None  # not a bowl
    u = (-2.0 * h22 * b1 + h12 * b2) / det
    v = (-2.0 * h11 * b2 + h12 * b1) / det
    return u, v


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("scene")
    ap.add_argument("out")
    ap.add_argument("--p", nargs=2, required=True, metavar=("KEY", "VALUES"))
    ap.add_argument("--q", nargs=2, required=True, metavar=("KEY", "VALUES"))
    ap.add_argument("--measured", required=True)
    ap.add_argument("--sigma", type=float, default=0.1)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--set", action="append", default=[])
    args = ap.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    pv = [float(s) for s in args.p[1].split(",")]
    qv = [float(s) for s in args.q[1].split(",")]
    measured = read_measured(args.measured)
    vshell = ROOT / "build" / "app" / "vshell"

    def run(i, j):
        d = out / f"p_{i}_q_{j}"
        if not (d / "cup_profile.csv").exists():
            cmd = [str(vshell), "run", args.scene, "-q", "-o", str(d), "--set",
                   f"{args.p[0]}={pv[i]!r}", "--set", f"{args.q[0]}={qv[j]!r}"]
            for s in args.set:
                cmd += ["--set", s]
            env = dict(os.environ, OMP_NUM_THREADS="1")
            with open(out / f"p_{i}_q_{j}.log", "w") as log:
                subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT, env=env)
        f = d / "cup_profile.csv"
        return (i, j, cost(read_profile(f), measured, args.sigma) if f.exists() else math.nan)

    grid = [(i, j) for i in range(len(pv)) for j in range(len(qv))]
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        results = sorted(pool.map(lambda ij: run(*ij), grid))
    with open(out / "cost_surface.csv", "w") as f:
        f.write(f"{args.p[0]},{args.q[0]},cost\n")
        for i, j, c in results:
            f.write(f"{pv[i]!r},{qv[j]!r},{c:.6g}\n")
    pm, ps = (pv[0] + pv[-1]) / 2, (pv[-1] - pv[0]) / 2
    qm, qs = (qv[0] + qv[-1]) / 2, (qv[-1] - qv[0]) / 2
    pts = [((pv[i] - pm) / ps, (qv[j] - qm) / qs, c) for i, j, c in results if math.isfinite(c)]
    failed = len(results) - len(pts)
    coef, resid = quadratic_fit(pts)
    rms = math.sqrt(sum(r * r for r in resid) / max(1, len(pts) - 6))
    best = min(pts, key=lambda t: t[2])
    print(f"grid {len(pv)} x {len(qv)}, {len(pts)} runs ({failed} failed)")
    print(f"lowest grid cost {best[2]:.2f} at {args.p[0]} {pm + ps * best[0]:.4g}, "
          f"{args.q[0]} {qm + qs * best[1]:.4g}")
    print(f"quadratic surface: cost scatter about it {rms:.2f} rms (the forward model's noise "
          f"plus the surface's misfit), largest {max(abs(r) for r in resid):.2f}")
    m = minimum(coef)
    if m is None:
        print("the fitted surface has no minimum (not a bowl)")
        return
    c_min = sum(a * f for a, f in zip(coef, [1.0, m[0], m[1], m[0] ** 2, m[0] * m[1], m[1] ** 2]))
    print(f"surface minimum {c_min:.2f} at {args.p[0]} {pm + ps * m[0]:.4f}, "
          f"{args.q[0]} {qm + qs * m[1]:.4f}")
    loo = []
    for k in range(len(pts)):
        ck, _ = quadratic_fit(pts[:k] + pts[k + 1:])
        mk = minimum(ck)
        if mk is not None:
            loo.append((pm + ps * mk[0], qm + qs * mk[1]))
    if loo:
        print(f"leave-one-out minima: {args.p[0]} {min(l[0] for l in loo):.4f}-"
              f"{max(l[0] for l in loo):.4f}, {args.q[0]} {min(l[1] for l in loo):.4f}-"
              f"{max(l[1] for l in loo):.4f} ({len(loo)} of {len(pts)} refits are bowls)")


if __name__ == "__main__":
    main()
