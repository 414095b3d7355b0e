#!/bin/bash
# Work against precision for ex4b (issue 14's CalculiX ratio; README section 5, "At equal accuracy"):
# vshell at several meshes and step settings, each timed on the machine's threads, its curves kept
# in results/wp/<label>/, its time in results/work_precision_vshell.csv; then work_precision.py
# measures every run against vshell's own converged reference (results/wp/ref_n48) and every
# CalculiX run against the CalculiX reference, and prints the ratio at equal accuracy.
#
#   work_precision.sh                 # the sweep (~5 min) and the table
#   work_precision.sh --reference     # first the vshell references (48 and 32 divisions, step
#                                     # converged: ~9 and ~3 min), then the sweep
#   work_precision.sh --table         # the table only (seconds)
#   VSHELL=path/to/vshell DIVISIONS="8 12 16" VARIANTS="default s1_cap05" work_precision.sh
#   DIVISIONS=16 VARIANTS="events_cap05 s3_cap05 ref5_cap05 theta1_cap05" work_precision.sh
#   FRICTION=3 work_precision.sh --reference   # the problem CalculiX solves, Coulomb mu = 3 instead
#                                              # of sticking: labels mu3_<label> (section 5, "The
#                                              # contact decides the ratio"); REFERENCES="48 32"
#                                              # sets the meshes
#
# Runs one after another (never two timed runs at once); the load average at each start goes into
# work_precision_vshell.csv.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
vshell=${VSHELL:-$root/build/app/vshell}
scene=$root/data/scenes/ex4b_square_clamped.toml
wp=$here/results/wp
times=$here/results/work_precision_vshell.csv
mkdir -p "$wp"
[ -f "$times" ] || echo "label,divisions,variant,unknowns,steps,factorisations,wall_s,cpu_user_s,load_1min_start,threads" > "$times"

# variant -> extra --set options
variant_sets() {
  # The scene's travel cap is 0.25 mm since 27 Nov 2026; the *_cap05 variants keep the 0.5 mm it
  # had before (section 5, "At equal accuracy").
  local c05="--set numerics.max_travel_increment_mm=0.5"
  case $1 in
    default) echo "" ;;                                           # the scene's defaults
    cap05) echo "$c05" ;;                                         # two solves, 0.5 mm
    s1_cap05) echo "$c05 --set numerics.implicit_solves=1" ;;     # one velocity solve per step
    s1_events_cap05) echo "$c05 --set numerics.implicit_solves=1 --set numerics.contact_events=true" ;;
    events_cap05) echo "$c05 --set numerics.contact_events=true" ;;  # the step study at 16
    s3_cap05) echo "$c05 --set numerics.implicit_solves=3" ;;
    ref5_cap05) echo "$c05 --set numerics.start_refinement=5" ;;
    theta1_cap05) echo "$c05 --set numerics.implicit_theta=1" ;;
    s2_fine) echo "--set numerics.implicit_solves=2 --set numerics.max_strain_increment=0.005 --set numerics.max_travel_increment_mm=0.125" ;;
    s2_finer) echo "--set numerics.implicit_solves=2 --set numerics.max_strain_increment=0.0025 --set numerics.max_travel_increment_mm=0.0625" ;;
    *) echo "unknown variant $1" >&2; exit 2 ;;
  esac
}

# FRICTION (a Coulomb coefficient, or unset: the scene's sticking punch) prefixes every label.
friction=${FRICTION:-}
prefix=${friction:+mu${friction}_}
friction_set=${friction:+--set tool.punch.friction=$friction}

run_one() {  # label divisions variant
  local label=$prefix$1 n=$2 variant=$3 out tf load wall user
  out=$(mktemp -d)
  tf=$(mktemp)
  load=$(cut -d' ' -f1 /proc/loadavg)
  # shellcheck disable=SC2046
  OMP_NUM_THREADS=${OMP_NUM_THREADS:-2} /usr/bin/time -f "%e %U" -o "$tf" "$vshell" run "$scene" \
    --set blank.divisions="$n" $friction_set $(variant_sets "$variant") --output "$out/run" > "$out/log" 2>&1 ||
    { echo "vshell failed for $label: $(tail -2 "$out/log")" >&2; exit 1; }
  read -r wall user < "$tf"
  rm -rf "${wp:?}/$label" && mkdir -p "$wp/$label"
  cp "$out"/run/load_travel.csv "$out"/run/strains_travel_*mm_{x,diagonal}.csv "$wp/$label/"
  python3 - "$out/run/run.json" "$label" "$n" "$variant" "$wall" "$user" "$load" \
    "${OMP_NUM_THREADS:-2}" >> "$times" <<'EOF'
import json, sys
d = json.load(open(sys.argv[1]))
label, n, variant, wall, user, load, th = sys.argv[2:]
print(f"{label},{n},{variant},{d['dofs']},{d['steps']},{d['timings']['factorisations']},{wall},{user},{load},{th}")
EOF
  rm -rf "$out" "$tf"
  echo "$label: ${wall} s wall"
}

mode=${1:-sweep}
if [ "$mode" = --reference ]; then
  for n in ${REFERENCES:-48 32}; do
    run_one "ref_n$n" "$n" s2_finer
  done
  if [ -z "$friction" ]; then
    run_one n16_s2_fine 16 s2_fine    # the step error at 16 divisions
    run_one n16_s2_finer 16 s2_finer
  fi
fi
if [ "$mode" != --table ]; then
  for variant in ${VARIANTS:-default cap05 s1_cap05 s1_events_cap05}; do
    for n in ${DIVISIONS:-8 10 12 14 16 20 24}; do
      run_one "n${n}_${variant}" "$n" "$variant"
    done
  done
fi
python3 "$here/work_precision.py" "$here/results" --csv "$here/results/work_precision.csv" \
  --svg "$here/results/work_precision.svg"
