#!/usr/bin/env python3
"""The part of a measured cup-height profile that no orthotropic (quarter) model can follow.

A quarter model with RD along x is symmetric about RD and TD, so its profile satisfies
h(t) = h(180 - t) = h(180 + t) = h(360 - t). The measured profile is split into that symmetric
part (the mean of the four mirror images, each read from the periodic piecewise-linear profile
through the points) and the rest. With the constant offset eliminated (shape_only), the rest gives
a floor under the calibration cost: 0.5 sum ((rest_i - mean(rest)) / sigma)^2.

    experiments/10_earing/orthotropic_floor.py [PROFILE] [--sigma MM]

Defaults: the ESAFORM 2021 profile (its last point, 359.954 deg, repeats the first ear and is left
out of the interpolation table but kept as a point, as in the calibration) and sigma = 0.1 mm (the
value of data/calibration/calibrate_earing_hill48.toml). Python 3 standard library only.
"""
import argparse
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT = os.path.join(HERE, "..", "..", "data", "measured", "esaform2021-aa6016t4-cup",
                       "AA6016_Experiment_Fig91_CupProfile_angle.txt")


def read_profile(path):
    rows = []
    with open(path) as f:
        for line in f:
            line = line.strip()
            if line and not line.startswith("#"):
                rows.append(tuple(float(x) for x in line.replace(",", " ").split()))
    return [r[0] for r in rows], [r[1] for r in rows]


def periodic(angles, heights):
    """The periodic piecewise-linear function through the points (one point per angle mod 360)."""
    table = sorted({round(a % 360.0, 9): h for a, h in zip(angles, heights)}.items())
    a = [t[0] for t in table]
    h = [t[1] for t in table]

    def f(t):
        t %= 360.0
        for i in range(len(a)):
            a0, a1 = a[i], a[(i + 1) % len(a)] + (360.0 if i + 1 == len(a) else 0.0)
            tt = t if t >= a0 else t + 360.0
            if a0 <= tt <= a1:
                return h[i] + (tt - a0) / (a1 - a0) * (h[(i + 1) % len(a)] - h[i])
        raise ValueError(t)

    return f


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("profile", nargs="?", default=DEFAULT)
    parser.add_argument("--sigma", type=float, default=0.1)
    args = parser.parse_args()
    angles, heights = read_profile(args.profile)
    # A last point within 1 deg of the first one plus 360 repeats it: keep it as a point only.
    table_angles, table_heights = angles, heights
    if len(angles) > 1 and angles[-1] - angles[0] > 359.0:
        table_angles, table_heights = angles[:-1], heights[:-1]
    f = periodic(table_angles, table_heights)
    sym = [(f(t) + f(180.0 - t) + f(180.0 + t) + f(360.0 - t)) / 4.0 for t in angles]
    rest = [h - s for h, s in zip(heights, sym)]
    mean_rest = sum(rest) / len(rest)
    floor = 0.5 * sum(((r - mean_rest) / args.sigma) ** 2 for r in rest)
    print(f"points: {len(angles)}")
    print(f"non-orthotropic part: rms {math.sqrt(sum(r * r for r in rest) / len(rest)):.4f} mm, "
          f"largest {max(abs(r) for r in rest):.4f} mm")
    print(f"cost floor of a shape-only fit with sigma {args.sigma} mm: {floor:.2f}")
    print(f"orthotropic part: amplitude {max(sym) - min(sym):.4f} mm "
          f"(the whole profile: {max(heights) - min(heights):.4f} mm)")
    for t in (0.0, 45.0, 90.0):
        print(f"orthotropic part at {t:4.0f} deg: {(f(t) + f(180 - t) + f(180 + t) + f(360 - t)) / 4:.4f} mm")


if __name__ == "__main__":
    main()
