#!/usr/bin/env python3
"""Print the Markdown tables of the README from results/comparison.csv, convergence.csv,
normal_stress.csv and elastic.csv (section 10).
Python 3 standard library only."""
import csv
import os
import sys

res = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "results")


def rows(name):
    p = os.path.join(res, name)
    return list(csv.DictReader(open(p))) if os.path.exists(p) else []


def table(name):
    by = {}
    for r in rows(name):
        by.setdefault(r["label"], []).append(r)
    for label, rs in by.items():
        print(f"\n**{label}**\n")
        print("| travel [mm] | F ref [N] | F other [N] | dF [%] | e3 ref (r0) | e3 other | de3 | "
              "max abs de3 (at r0 [mm]) | rms de3 |")
        print("|---|---|---|---|---|---|---|---|---|")
        for r in rs:
            s = (f"| {float(r['punch_travel_mm']):g} | {float(r['force_ref_N']):.0f} | "
                 f"{float(r['force_other_N']):.0f} | {float(r['force_error_pct']):+.2f} |")
            if r.get("eps3_pole_ref"):
                s += (f" {float(r['eps3_pole_ref']):.4f} ({float(r['pole_r0_mm']):.2f}) | "
                      f"{float(r['eps3_pole_other']):.4f} | {float(r['eps3_pole_diff']):+.4f} | "
                      f"{float(r['eps3_max_abs_diff']):.4f} ({float(r['eps3_max_diff_r0_mm']):.1f})"
                      f" | {float(r['eps3_rms_diff']):.4f} |")
            else:
                s += " | | | | |"
            print(s)


for n in ("comparison.csv", "convergence.csv", "normal_stress.csv"):
    print(f"\n### {n}")
    table(n)


def elastic_table(name="elastic.csv"):
    """Section 10: one row per case and travel, the variants of compare_elastic.sh side by side."""
    variants = ("off", "strains", "start", "both")
    by = {}
    for r in rows(name):
        case, variant = r["label"].rsplit("_", 1)
        by.setdefault(case, {}).setdefault(r["punch_travel_mm"], {})[variant] = r
    if not by:
        return
    print(f"\n### {name}\n")
    print("| case | travel [mm] | dF off | dF start | pole de3 off | strains | start | both | "
          "max abs de3 off | strains | start | both | rms de3 off | strains | start | both |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for case, travels in by.items():
        for t, vs in travels.items():
            def f(v, key, fmt):
                r = vs.get(v)
                return format(float(r[key]), fmt) if r and r.get(key) else ""
            cells = [case, f"{float(t):g}",
                     f("off", "force_error_pct", "+.2f"), f("start", "force_error_pct", "+.2f")]
            cells += [f(v, "eps3_pole_diff", "+.4f") for v in variants]
            cells += [f(v, "eps3_max_abs_diff", ".4f") for v in variants]
            cells += [f(v, "eps3_rms_diff", ".4f") for v in variants]
            print("| " + " | ".join(cells) + " |")


elastic_table()
