#!/usr/bin/env python3
"""The table of contact_mesh.sh: for each contact law (friction 0, Coulomb 0.2, sticking) the
force difference at 2 / 3 / 5 / 7.5 / 10 mm and the RMS thickness-strain difference at 5 and
10 mm (along x, r0 <= 50 mm, and the diagonal, r0 <= 70.7 mm) of 8-24 divisions against the
same law's 32-division run.

  contact_mesh.py RESULTS/contact_mesh

Python 3 standard library only.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare  # noqa: E402  (load_curve, interp, line_difference)

FORCE_TRAVELS = (2.0, 3.0, 5.0, 7.5, 10.0)
PROFILE_TRAVELS = (5.0, 10.0)


def main():
    root = sys.argv[1]
    print("law       div  force difference at 2 / 3 / 5 / 7.5 / 10 mm [%]     RMS d eps_t at 5 / 10 mm (x, diagonal)")
    for law in ("0", "0.2", "sticking"):
        ref = os.path.join(root, f"f{law}_n32")
        if not os.path.isdir(ref):
            continue
        fx, fy = compare.load_curve(ref)
        for n in (8, 12, 16, 24):
            run = os.path.join(root, f"f{law}_n{n}")
            if not os.path.isdir(run):
                continue
            ox, oy = compare.load_curve(run)
            df = [100.0 * (compare.interp(ox, oy, T) / compare.interp(fx, fy, T) - 1.0)
                  for T in FORCE_TRAVELS]
            rms = [compare.line_difference(ref, run, T, line)[0]
                   for T in PROFILE_TRAVELS for line in ("x", "diagonal")]
            print(f"{law:9} {n:3d}  " + " / ".join(f"{x:+.2f}" for x in df) + "    " +
                  " ".join(f"{x:.4f}" for x in rms))


if __name__ == "__main__":
    main()
