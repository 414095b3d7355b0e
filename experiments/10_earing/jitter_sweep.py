#!/usr/bin/env python3
"""Jitter of the cup-height profile over a parameter sweep (jitter_sweep.sh): writes heights.csv
(the rim height per angle and run) and prints, per rim point, the largest deviation of the N heights from their least-squares line in the parameter, the line's
change over one finite-difference step, and the same for the mean height and the amplitude."""
import csv
import sys
from pathlib import Path


def heights(path):
    rows = [r for r in csv.reader(open(path)) if r and not r[0].startswith("#")]
    head = rows[0]
    a, h = head.index("angle_from_rd_deg"), head.index("cup_height_mm")
    return [float(r[a]) for r in rows[1:]], [float(r[h]) for r in rows[1:]]


def line_fit(x, y):
    n = len(x)
    mx, my = sum(x) / n, sum(y) / n
    sxx = sum((v - mx) ** 2 for v in x)
    slope = sum((u - mx) * (v - my) for u, v in zip(x, y)) / sxx
    dev = max(abs(v - (my + slope * (u - mx))) for u, v in zip(x, y))
    return slope, dev


def main():
    out = Path(sys.argv[1])
    fd_step = float(sys.argv[2]) if len(sys.argv) > 2 else 0.01
    values = {int(k): float(v) for k, v in (l.split() for l in open(out / "values.txt"))}
    runs = []
    for k in sorted(values):
        f = out / f"run_{k}" / "cup_profile.csv"
        if f.exists():
            runs.append((values[k], *heights(f)))
    if len(runs) < 3:
        sys.exit("fewer than 3 finished runs")
    x = [r[0] for r in runs]
    angles = runs[0][1]
    with open(out / "heights.csv", "w") as f:
        f.write("angle_from_rd_deg," + ",".join(f"cup_height_mm_at_{v!r}" for v in x) + "\n")
        for i, ang in enumerate(angles):
            f.write(f"{ang:g}," + ",".join(f"{r[2][i]:.7g}" for r in runs) + "\n")
    worst = (0.0, 0.0, 0.0)
    for i, ang in enumerate(angles):
        slope, dev = line_fit(x, [r[2][i] for r in runs])
        worst = max(worst, (dev, ang, slope))
    mean_slope, mean_dev = line_fit(x, [sum(r[2]) / len(r[2]) for r in runs])
    amp_slope, amp_dev = line_fit(x, [max(r[2]) - min(r[2]) for r in runs])
    print(f"runs {len(runs)}, parameter {x[0]:.6g} .. {x[-1]:.6g}")
    print(f"rim height: largest deviation from the line {worst[0]:.4g} mm at {worst[1]:.1f} deg "
          f"(slope there {worst[2]:.4g} mm per unit, {worst[2] * fd_step:.4g} mm per step {fd_step:g})")
    print(f"mean height: deviation {mean_dev:.4g} mm, slope {mean_slope:.4g} mm per unit "
          f"({mean_slope * fd_step:.4g} mm per step)")
    print(f"amplitude: deviation {amp_dev:.4g} mm, slope {amp_slope:.4g} mm per unit "
          f"({amp_slope * fd_step:.4g} mm per step)")


if __name__ == "__main__":
    main()
