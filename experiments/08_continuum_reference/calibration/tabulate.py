#!/usr/bin/env python3
"""results/calibration_elastic.csv from the report folders of the section-10 calibrations.

    python3 tabulate.py REPORT_ROOT > ../results/calibration_elastic.csv

REPORT_ROOT holds one folder per config, named after it without .toml (vshell calibrate
CONFIG.toml -o REPORT_ROOT/CONFIG). Truth: friction 0.1, Swift K 589 MPa, n 0.216.
"""
import json
import os
import sys

CONFIGS = [
    "calibrate_ex1_mu010_contact_from10",
    "calibrate_ex1_mu010_contact_start_from10",
    "calibrate_ex1_mu010_contact_elastic",
    "calibrate_ex1_mu010_contact_elastic_from10",
    "calibrate_ex1_mu010_contact_elastic_from10_sigma",
]
TRUTH = {"tool.punch.friction": 0.1, "material.hardening.K_MPa": 589.0, "material.hardening.n": 0.216}


def g(x):
    return "" if x is None else f"{x:.6g}"


def main(root):
    sys.stdout.reconfigure(newline="\r\n")  # the stored results have CRLF line ends
    print("config,parameter,truth,value,interval_lower,interval_upper,error_pct,"
          "model_form_lower,model_form_upper,forward_runs,lack_of_fit")
    for config in CONFIGS:
        with open(os.path.join(root, config, "calibration.json")) as f:
            j = json.load(f)
        verdicts = ";".join(f"{d['name']}:{d['lack_of_fit']['verdict']}" for d in j["data_sets"])
        for p in j["parameters"]:
            if p["fixed"]:
                continue
            truth = TRUTH[p["address"]]
            print(",".join([
                config + ".toml", p["address"], repr(truth), g(p["value"]),
                g(p.get("interval_lower")), g(p.get("interval_upper")),
                f"{100.0 * (p['value'] - truth) / truth:.2f}",
                g(p.get("model_form_lower")), g(p.get("model_form_upper")),
                str(j["forward_runs"]), verdicts]))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "/tmp/cal")
