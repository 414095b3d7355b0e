#!/usr/bin/env python3
"""Work against precision for ex4b: every vshell run of results/wp/ against vshell's converged
reference of the same problem (results/wp/ref_n48 for the scene's sticking punch,
results/wp/mu<MU>_ref_n48 or _n32 for runs labelled mu<MU>_*, Coulomb friction MU), every
CalculiX run against the CalculiX reference of its problem (CCX_PROBLEMS: mu = 3, the stand-in
for sticking, and mu = 0.2), and the ratio of run times at equal accuracy per problem (README
section 5, "At equal accuracy" and "The contact decides the ratio").

  work_precision.py RESULTS_DIR [--csv OUT.csv] [--svg OUT.svg]

Each tool is measured against its own converged answer: the two models differ (section 4), so
"equal accuracy" means equal discretisation error, the error a user buys down with run time.
Errors over the outputs at 5, 10, 15, 20 mm: the largest |dF| / F, and the largest RMS
difference of the thickness-strain profiles along x (0 <= r0 <= 50 mm) and the diagonal
(r0 <= 70.7 mm). Times: results/work_precision_vshell.csv (vshell) and time.txt (CalculiX).
Python 3 standard library only.
"""
import argparse
import csv
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare  # noqa: E402  (load_curve, interp, line_difference)

TRAVELS = (5.0, 10.0, 15.0, 20.0)
# In results/wp/, behind the label's problem prefix (problem_of): the finest one there.
VSHELL_REFS = ("ref_n48", "ref_n32")
# The CalculiX problems: friction -> (reference, {run that reached 20 mm: the run whose
# time.txt times it on the 2-core AMD EPYC, two threads}). mu = 3 stands in for the shell's
# sticking punch (section 1).
CCX_PROBLEMS = {
    "3": ("ex4b_n16_l3_k25e3_mu3",
          {"ex4b_n12_l2_k5e4_mu3": "ex4b_n12_l2_k5e4_mu3_t2_zen5",
           "ex4b_n16_l2_k25e3_mu3_t2_zen5": "ex4b_n16_l2_k25e3_mu3_t2_zen5"}),
    "0.2": ("ex4b_n16_l3_k25e3_mu02",
            {"ex4b_n12_l2_k5e4_mu02_t2": "ex4b_n12_l2_k5e4_mu02_t2"}),
}


# The CalculiX problem that stands in for the shell's sticking punch.
CCX_STICKING = "3"


def errors(ref, other):
    """(max |dF| %, max RMS de3, max |de3|) over TRAVELS, lines x and diagonal."""
    fx, fy = compare.load_curve(ref)
    ox, oy = compare.load_curve(other)
    df = rms_max = abs_max = 0.0
    for T in TRAVELS:
        F0, F1 = compare.interp(fx, fy, T), compare.interp(ox, oy, T)
        df = max(df, abs(100.0 * (F1 - F0) / F0))
        for line in ("x", "diagonal"):
            rms, biggest = compare.line_difference(ref, other, T, line)
            rms_max = max(rms_max, rms)
            abs_max = max(abs_max, biggest)
    return df, rms_max, abs_max


def problem_of(label):
    """The problem prefix of a vshell label: "mu3_" for a Coulomb coefficient set by
    work_precision.sh's FRICTION, "" for the scene's sticking punch."""
    head = label.split("_", 1)[0]
    return head + "_" if head.startswith("mu") else ""


def friction_of(label):
    """The punch friction of a vshell label: the Coulomb coefficient ("3", "0.2") or "sticking"."""
    return problem_of(label)[2:-1] or "sticking"


def vshell_reference(res, label):
    """The converged vshell run of the label's problem: the finest of VSHELL_REFS there, or None."""
    for ref in VSHELL_REFS:
        d = os.path.join(res, "wp", problem_of(label) + ref)
        if os.path.isdir(d):
            return d
    return None


def ccx_wall(path):
    with open(path) as f:
        last = [ln for ln in f if ln.strip()][-1]  # the last timing of the case
    fields = dict(kv.split("=", 1) for kv in last.split() if "=" in kv)
    return float(fields["wall_s"]), float(fields["cpu_user_s"]), int(fields.get("threads", "1"))


def write_svg(rows, path):
    """Two log-log panels (force error, RMS thickness-strain error against wall time), one
    polyline per vshell variant (meshes in order), CalculiX runs as squares."""
    series = {}
    for r in rows:
        run = r["run"][len(problem_of(r["run"])):]
        variant = run.split("_", 1)[-1]
        if r["tool"] == "ccx":
            key = "CalculiX mu = " + r["friction"]
        elif run.startswith("n16_s2"):
            key = "vshell 16 div., finer steps"
        elif r["friction"] == "sticking":
            key = "vshell " + variant
        else:
            key = "vshell mu = " + r["friction"] + ", " + variant
        series.setdefault(key, []).append(r)
    series = {k: v for k, v in series.items() if k.startswith("CalculiX") or len(v) > 1}  # no single runs
    colours = ["#1f77b4", "#ff7f0e", "#2ca02c", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f",
               "#bcbd22", "#17becf", "#d62728"]
    W, H, m = 440, 330, 55
    t_lo, t_hi = 0.2, 1000.0
    legend_rows = (len(series) + 3) // 4
    height = H + 60 + 14 * legend_rows
    panels = [("force_err_pct", "max |dF| / F [%]", 0.1, 10.0),
              ("rms_de3", "max RMS d eps_t", 0.001, 0.03)]
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{2 * W}" height="{height}" '
           'font-family="sans-serif" font-size="11">',
           f'<rect width="{2 * W}" height="{height}" fill="white"/>']
    for k, (field, label, y_lo, y_hi) in enumerate(panels):
        x0 = k * W + m

        def X(t):
            return x0 + (W - m - 15) * math.log(t / t_lo) / math.log(t_hi / t_lo)

        def Y(v):
            v = min(max(v, y_lo), y_hi)
            return H - m + 15 - (H - m - 10) * math.log(v / y_lo) / math.log(y_hi / y_lo)

        out.append(f'<rect x="{X(t_lo):.1f}" y="{Y(y_hi):.1f}" width="{X(t_hi) - X(t_lo):.1f}" '
                   f'height="{Y(y_lo) - Y(y_hi):.1f}" fill="none" stroke="black"/>')
        for t in (1, 10, 100, 1000):
            out.append(f'<text x="{X(t):.1f}" y="{Y(y_lo) + 14:.1f}" text-anchor="middle">{t}</text>')
        for v in ((0.1, 0.3, 1, 3, 10) if field == "force_err_pct" else (0.001, 0.002, 0.005, 0.01, 0.03)):
            out.append(f'<text x="{X(t_lo) - 4:.1f}" y="{Y(v) + 4:.1f}" text-anchor="end">{v:g}</text>')
            out.append(f'<line x1="{X(t_lo):.1f}" x2="{X(t_hi):.1f}" y1="{Y(v):.1f}" y2="{Y(v):.1f}" '
                       'stroke="#ddd"/>')
        out.append(f'<text x="{(X(t_lo) + X(t_hi)) / 2:.1f}" y="{Y(y_lo) + 30:.1f}" '
                   'text-anchor="middle">wall time [s], 2 threads</text>')
        out.append(f'<text x="{X(t_lo):.1f}" y="{Y(y_hi) - 6:.1f}">{label}</text>')
        for j, (name, pts) in enumerate(sorted(series.items())):
            c = "black" if name == "CalculiX mu = 3" else colours[j % len(colours)]
            ccx = name.startswith("CalculiX")
            pts = sorted(pts, key=lambda r: r["wall_s"])
            if not ccx and len(pts) > 1:
                d = " ".join(f"{X(r['wall_s']):.1f},{Y(r[field]):.1f}" for r in pts)
                out.append(f'<polyline points="{d}" fill="none" stroke="{c}"/>')
            for r in pts:
                if ccx:
                    out.append(f'<rect x="{X(r["wall_s"]) - 4:.1f}" y="{Y(r[field]) - 4:.1f}" '
                               f'width="8" height="8" fill="{c}"/>')
                else:
                    out.append(f'<circle cx="{X(r["wall_s"]):.1f}" cy="{Y(r[field]):.1f}" r="2.5" '
                               f'fill="{c}"/>')
            if k == 0:
                out.append(f'<text x="{m + 200 * (j % 4)}" y="{H + 50 + 14 * (j // 4)}" '
                           f'fill="{c}">{name}</text>')
    out.append(f'<text x="{m}" y="{H + 50 + 14 * legend_rows}">ex4b to 20 mm: each tool against its own converged '
               'answer of the same problem (vshell 48 divisions, CalculiX 16 x 16 x 3)</text>')
    out.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("results")
    p.add_argument("--csv", default=None)
    p.add_argument("--svg", default=None, help="error against wall time, log-log, both errors")
    a = p.parse_args()
    res = a.results
    times = {}
    with open(os.path.join(res, "work_precision_vshell.csv")) as f:
        for r in csv.DictReader(f):
            times[r["label"]] = r  # the last timing of a label wins
    rows = []
    for label, t in sorted(times.items(), key=lambda kv: (problem_of(kv[0]), kv[1]["variant"],
                                                          int(kv[1]["divisions"]))):
        d = os.path.join(res, "wp", label)
        vref = vshell_reference(res, label)
        if vref is None or os.path.basename(vref) == label or not os.path.isdir(d):
            continue
        df, rms, mx = errors(vref, d)
        rows.append(dict(tool="vshell", run=label, unknowns=int(t["unknowns"]), steps=int(t["steps"]),
                         wall_s=float(t["wall_s"]), cpu_s=float(t["cpu_user_s"]), threads=t["threads"],
                         force_err_pct=df, rms_de3=rms, max_de3=mx,
                         friction=friction_of(label)))
    for mu, (ref, runs) in CCX_PROBLEMS.items():
        cref = os.path.join(res, ref)
        for run, timing in runs.items():
            tpath = os.path.join(res, timing, "time.txt")
            if not os.path.isdir(cref) or not os.path.exists(tpath):
                continue
            wall, cpu, threads = ccx_wall(tpath)
            df, rms, mx = errors(cref, os.path.join(res, run))
            rows.append(dict(tool="ccx", run=run, unknowns=0, steps=0, wall_s=wall, cpu_s=cpu,
                             threads=str(threads), force_err_pct=df, rms_de3=rms, max_de3=mx,
                             friction=mu))
    print(f"{'tool':6} {'run':24} {'unknowns':>8} {'steps':>5} {'wall s':>7} {'cpu s':>7} "
          f"{'|dF| %':>7} {'rms de3':>8} {'max de3':>8}")
    for r in rows:
        print(f"{r['tool']:6} {r['run']:24} {r['unknowns']:8d} {r['steps']:5d} {r['wall_s']:7.2f} "
              f"{r['cpu_s']:7.2f} {r['force_err_pct']:7.3f} {r['rms_de3']:8.4f} {r['max_de3']:8.4f}")
    for mu in sorted({r["friction"] for r in rows if r["tool"] == "vshell"}, reverse=True):
        name = "the scene's sticking punch" if mu == "sticking" else f"Coulomb mu = {mu}"
        ccx_mu = CCX_STICKING if mu == "sticking" else mu
        print(f"\nAt equal accuracy, vshell with {name}: the fastest vshell run whose force and "
              "RMS thickness-strain errors are both at most the CalculiX run's")
        for c in (r for r in rows if r["tool"] == "ccx" and r["friction"] == ccx_mu):
            ok = [r for r in rows if r["tool"] == "vshell" and r["friction"] == mu
                  and r["force_err_pct"] <= c["force_err_pct"] and r["rms_de3"] <= c["rms_de3"]]
            if not ok:
                print(f"  {c['run']}: no vshell run is as accurate")
                continue
            best = min(ok, key=lambda r: r["wall_s"])
            print(f"  {c['run']} ({c['wall_s']:.0f} s, {c['force_err_pct']:.2f} %, "
                  f"{c['rms_de3']:.4f}): {best['run']} ({best['wall_s']:.2f} s, "
                  f"{best['force_err_pct']:.2f} %, {best['rms_de3']:.4f}): ratio "
                  f"{c['wall_s'] / best['wall_s']:.0f}x in wall time")
    if a.svg:
        write_svg(rows, a.svg)
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0]))
            w.writeheader()
            for r in rows:
                w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})


if __name__ == "__main__":
    main()
