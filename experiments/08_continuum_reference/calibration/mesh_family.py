#!/usr/bin/env python3
"""How the identified friction depends on the shell's mesh (README section 12). The winning config
of section 10 (calibrate_ex1_mu010_contact_elastic_from10.toml: full elastic correction,
normal-stress term, load from 10 mm) refitted with blank.elements = 30 ... 120, each a few
seconds, and a forward run of each mesh at the truth (friction 0.1, K 589 MPa, n 0.216) whose
thickness profile at 25 mm gives the element-scale ripple:

  * ripple: rms over 5 <= r0 <= 30 mm of (e[i-1] - 2 e[i] + e[i+1]) / 4, the element
    thickness strains' second difference (an odd-even zigzag of amplitude a gives a; a smooth
    profile gives L^2 e'' / 4, which falls 4x per halving of the element length L);
  * holes: elements inside the punch contact patch (between its first and last touching
    element with r0 < 45 mm; the die shoulder touches from r0 ~ 48 mm) with neither node
    touching.

    python3 mesh_family.py [BUILD_VSHELL] > ../results/calibration_mesh.csv

run from this folder; the variant configs and reports go to a temporary folder.
"""
import csv
import json
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
BASE = "calibrate_ex1_mu010_contact_elastic_from10.toml"
TRUTH = {"tool.punch.friction": 0.1, "material.hardening.K_MPa": 589.0, "material.hardening.n": 0.216}
MESHES = (30, 40, 50, 60, 70, 80, 100, 120)
BLANK_RADIUS_MM, THICKNESS_MM = 59.18, 0.85  # data/scenes/ex1_hemispherical_stretching.toml


def variant_config(base_text, folder, elements):
    """The base config at `elements` elements, without its model-form refits, with absolute
    scene and data paths."""
    text = base_text.split("# Model-form alternatives")[0]
    text = text.replace('scene = "../', f'scene = "{HERE}/../')
    text = re.sub(r'file = "([^"]+)"', lambda m: f'file = "{os.path.join(HERE, m.group(1))}"', text)
    text = re.sub(r'"blank.elements" = \d+', f'"blank.elements" = {elements}', text)
    path = os.path.join(folder, "config.toml")
    with open(path, "w") as f:
        f.write(text + '[output]\ndirectory = "out"\n')
    return path, text


def forward_sets(config_text):
    """The config's [forward.set] edits as vshell run --set arguments."""
    block = config_text.split("[forward.set]", 1)[1]
    args = []
    for line in block.splitlines():
        m = re.match(r'\s*"([^"]+)"\s*=\s*(.+?)\s*$', line)
        if m:
            args += ["--set", f"{m.group(1)}={m.group(2).strip(chr(34))}"]
        elif line.startswith("["):
            break
    return args


def ripple_and_holes(profile_csv):
    with open(profile_csv) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    r0 = [float(r["r0_mm"]) for r in rows]
    e = [float(r["eps_thickness"]) for r in rows]
    c = [int(r["contact"]) for r in rows]
    d2 = [(e[i - 1] - 2 * e[i] + e[i + 1]) / 4 for i in range(1, len(e) - 1) if 5 <= r0[i] <= 30]
    # The punch patch: the die touches from r0 ~ 48 mm on (the shoulder), the punch's edge is at
    # r0 ~ 31 mm at 25 mm of travel.
    touching = [i for i, flag in enumerate(c) if flag and r0[i] < 45.0]
    holes = sum(1 for i in range(touching[0], touching[-1] + 1) if not c[i]) if touching else 0
    return (sum(x * x for x in d2) / len(d2)) ** 0.5, holes


def main():
    vshell = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "../../../build/app/vshell")
    scene = os.path.join(HERE, "../../../data/scenes/ex1_hemispherical_stretching.toml")
    with open(os.path.join(HERE, BASE)) as f:
        base_text = f.read()
    w = csv.writer(sys.stdout, lineterminator="\n")
    w.writerow(["elements", "element_length_per_thickness", "friction", "friction_lower",
                "friction_upper", "friction_error_pct", "K_MPa", "K_error_pct", "n",
                "n_error_pct", "final_cost", "termination", "forward_runs", "forward_warns",
                "ripple_eps_thickness_25mm", "contact_holes_25mm"])
    with tempfile.TemporaryDirectory() as tmp:
        for elements in MESHES:
            folder = os.path.join(tmp, str(elements))
            os.makedirs(folder)
            config, text = variant_config(base_text, folder, elements)
            subprocess.run([vshell, "calibrate", config, "-o", os.path.join(folder, "out")],
                           check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                           cwd=folder)
            with open(os.path.join(folder, "out", "calibration.json")) as f:
                j = json.load(f)
            truth_args = [a for k, v in TRUTH.items() for a in ("--set", f"{k}={v}")]
            subprocess.run([vshell, "run", scene, "-q", *forward_sets(text), *truth_args,
                            "--set", "process.output_travels_mm=[25]", "-o",
                            os.path.join(folder, "truth")],
                           check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            ripple, holes = ripple_and_holes(
                os.path.join(folder, "truth", "strains_travel_025.00mm.csv"))
            p = {q["address"]: q for q in j["parameters"]}
            err = {a: 100.0 * (p[a]["value"] - TRUTH[a]) / TRUTH[a] for a in TRUTH}
            fr = p["tool.punch.friction"]
            w.writerow([elements, f"{BLANK_RADIUS_MM / elements / THICKNESS_MM:.3f}",
                        f"{fr['value']:.6g}", f"{fr['interval_lower']:.6g}",
                        f"{fr['interval_upper']:.6g}", f"{err['tool.punch.friction']:.2f}",
                        f"{p['material.hardening.K_MPa']['value']:.6g}",
                        f"{err['material.hardening.K_MPa']:.2f}",
                        f"{p['material.hardening.n']['value']:.6g}",
                        f"{err['material.hardening.n']:.2f}", f"{j['final_cost']:.4g}",
                        j["termination"], j["forward_runs"],
                        "yes" if j.get("forward_warnings") else "no", f"{ripple:.3g}", holes])
            sys.stdout.flush()


if __name__ == "__main__":
    main()
