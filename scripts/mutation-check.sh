#!/usr/bin/env bash
# Mutation check (issue 18): plants plausible bugs, one at a time, at the formulas that matter in
# a scratch copy of the tree, rebuilds, runs the CI tests and reports which tests kill each one.
# Not part of CI. On the shared 2-core machine, after the first build of the scratch copy: about
# 1-1.5 min per mutation with every failing test named, except those that break a Newton tangent
# (10+ min each); with MUT_FAIL_FAST=1 all of them in ~10 min (docs/mutation-check.md).
#
#   scripts/mutation-check.sh                 # every mutation
#   MUT_FAIL_FAST=1 scripts/mutation-check.sh # every mutation, the first killing test only
#   scripts/mutation-check.sh hill_1p2r ...   # the named ones (develop a test against one)
#   scripts/mutation-check.sh --list          # the list
#
# Environment: MUT_DIR (scratch, default /tmp/vs-mutation; kept between runs so that a rebuild
# is incremental), MUT_JOBS (build jobs, default 2), MUT_TIMEOUT (seconds per test binary,
# default 900: a mutation that makes a run hang is counted as killed by the timeout), MUT_FILTER
# (a gtest filter that replaces the default one: for a single-mutation rerun against the tests
# that should kill it; the default runs the CI tests less SLOW), MUT_ALL_BINARIES=1 (also run
# the test binaries that the mutation left byte-identical, see below), MUT_FAIL_FAST=1 (stop at the
# first failed test: each binary runs with --gtest_fail_fast and the binaries still running are
# stopped once one has failed; the table then names the first killing tests, not all of them.
# A mutation that breaks the Newton tangent makes the friction runs crawl to their iteration
# limits, up to the timeout; this mode gives the verdict in seconds).
#
# The scratch tree is MUT_DIR/tree, copied from this repository (build/ and .git excluded), with
# its build in MUT_DIR/tree/build: the same layout as a checkout with build/ inside, so that with
# CCACHE_BASEDIR set to the scratch folder ccache reuses objects from a build of the repository
# made with CCACHE_BASEDIR set to its parent.
#
# Tests: every CI test binary except the tests listed in SLOW below (each > 10 s; they compare
# runs that the faster tests already exercise). A mutation killed by this subset is killed by
# the CI suite. A test binary whose bytes the mutated build leaves identical to the unmutated
# build's (it does not link the mutated code: the inverse/ mutations and vs_physics_tests, for
# instance) is not rerun: it would run the same instructions as in the baseline, which passed.
# Output: one line per mutation, the killing tests, and `killed K of N`.
set -u -o pipefail

ROOT=$(cd "$(dirname "$0")/.." && pwd)
MUT_DIR=${MUT_DIR:-/tmp/vs-mutation}
JOBS=${MUT_JOBS:-2}
TIMEOUT=${MUT_TIMEOUT:-900}
FILTER=${MUT_FILTER:-}
ALL_BINARIES=${MUT_ALL_BINARIES:-0}
FAIL_FAST=${MUT_FAIL_FAST:-0}
TREE=$MUT_DIR/tree
BUILD=$TREE/build
BINARIES=(vs_physics_tests vs_shell3d_tests vs_system_tests vs_inverse_tests)
SLOW='Calibration3d.*:CalibrationSystem.*:Forming3dHolder.*:Forming3d.GoalNumerics*'
SLOW+=':Forming3dSticking.MatchesAxisymmetricSolverAt8mm:FullBlankForming.Disc*'
SLOW+=':SpeedTiming.*'

# name | file | literal text | replacement | what the bug is
MUTATIONS=$(cat <<'EOF'
hill_1p2r|forward/material/viscous_law.cc|3.0 * (1.0 + R) / (1.0 + 2.0 * R)|3.0 * (1.0 + R) / (2.0 + R)|axisymmetric Hill factor (1+2R) written (2+R)
hill3d_1p2r|forward/material/hill_plane_stress.cc|3.0 * (1.0 + R) / (1.0 + 2.0 * R)|3.0 * (1.0 + R) / (2.0 + R)|3D Hill factor (1+2R) written (2+R)
swift_eps0|forward/material/hardening.cc|return spec_.K_MPa * std::pow(spec_.eps0 + eps, spec_.n);|return spec_.K_MPa * std::pow(eps + 1e-3, spec_.n);|Swift law without its eps0
swift_slope|forward/material/hardening.cc|return spec_.K_MPa * spec_.n * std::pow(spec_.eps0 + eps, spec_.n - 1.0);|return spec_.K_MPa * std::pow(spec_.eps0 + eps, spec_.n - 1.0);|Swift hardening slope without its factor n
coulomb_2pi|forward/contact/coulomb.h|t.force = limit * kTwoOverPi * at;|t.force = limit * at;|Coulomb force without 2/pi (both geometries)
coulomb_tangent|forward/contact/coulomb.h|(v0 * (1.0 + a * a))|(v0 * (1.0 + a))|Coulomb tangent with 1 + a instead of 1 + a^2
axi_friction_2pi|forward/model/axisym_model.cc|tangent_weight * mu * kTwoOverPi * std::atan|tangent_weight * mu * std::atan|axisymmetric consistent-friction tangent without 2/pi
axi_holder_friction|forward/model/axisym_model.cc|if (c.on_die_face) limit += holder_friction_ * c.holder_force_N;|if (c.on_die_face) limit += 0.0 * holder_friction_ * c.holder_force_N;|axisymmetric holder friction dropped
shell3d_friction_half|forward/model/forming_model.cc|const double limit = friction_limit(c);|const double limit = 0.5 * friction_limit(c);|3D friction force halved
shell3d_thickness_sqrt|forward/stepping/shell3d_driver.cc|const double h = model_.initial_thickness() / stretch[i];|const double h = model_.initial_thickness() / std::sqrt(stretch[i]);|3D thickness h0/sqrt(stretch)
axi_thickness_radius|forward/stepping/axisym_driver.cc|const double area = 2.0 * std::numbers::pi * g.mid_radius() * g.length();|const double area = 2.0 * std::numbers::pi * s.x[e].x() * g.length() + 1e-9;|axisymmetric thickness from the inner node's radius
contact_event_late|forward/contact/rigid_tool.cc|      return hi;|      return 2.0 * hi;|contact event placed at twice its time
heun_no_average|forward/stepping/step_driver.h|const Solved mid = g_.blend(from, pred, 0.5);|const Solved mid = g_.blend(from, pred, 1.0);|Heun update without the average (corrector only; both geometries)
heun3d_no_average|forward/stepping/shell3d_driver.cc|mid.state.velocity[i] = (1.0 - w) * a.state.velocity[i] + w * b.state.velocity[i];|mid.state.velocity[i] = a.state.velocity[i];|3D geometry update with the start velocity only (Heun's mean -> Euler; implicit too)
implicit_blend_end_rate|forward/stepping/step_driver.h|const Solved moving = g_.blend(from, previous, theta);|const Solved moving = g_.blend(from, previous, 1.0);|implicit update moving the geometry with the end-of-step rates whatever theta (backward Euler)
holder3d_share|forward/model/forming_model.cc|const double share = holder_force_ / symmetry_factor();|const double share = holder_force_;|3D holder force not divided among the quarter
calib_weight|inverse/calibrate.cc|? 1.0 / d.measurement.point_sigma[i]|? 1.0 / (d.measurement.point_sigma[i] * d.measurement.point_sigma[i])|calibration residual scaled by 1/sigma^2
covariance_variance|inverse/uncertainty.cc|2.0 * cost / static_cast<double>(m - p)|cost / static_cast<double>(m - p)|covariance residual variance halved
EOF
)

list() { echo "$MUTATIONS" | awk -F'|' '{printf "%-24s %-40s %s\n", $1, $2, $5}'; }
if [[ ${1:-} == --list ]]; then list; exit 0; fi

selected=("$@")
wanted() {
  [[ ${#selected[@]} -eq 0 ]] && return 0
  local s
  for s in "${selected[@]}"; do [[ $s == "$1" ]] && return 0; done
  return 1
}

# Literal, exactly-once replacement (fails if the text is missing or ambiguous).
replace() {
  python3 - "$1" "$2" "$3" <<'PY'
import sys
path, old, new = sys.argv[1:4]
text = open(path).read()
n = text.count(old)
if n != 1:
    sys.exit(f"{path}: the text occurs {n} times: {old!r}")
open(path, "w").write(text.replace(old, new))
PY
}

export CCACHE_BASEDIR=$MUT_DIR
mkdir -p "$TREE"
echo "scratch tree: $TREE"
# A plain copy keeps the sources' times, so an unchanged file is not rebuilt (no rsync needed).
tar -C "$ROOT" --exclude=./build --exclude=./.git -cf - . | tar -C "$TREE" -xf -
# Files deleted from the repository go from the copy too (the tests are globbed).
(cd "$TREE" && find . -path ./build -prune -o -type f -print) | while read -r f; do
  [[ -e $ROOT/$f ]] || rm -f "$TREE/$f"
done
# A run stopped while a mutation was planted: the copy above restored the file with its old time,
# older than the mutated objects; touch it so that it is rebuilt.
if [[ -f $MUT_DIR/mutated ]]; then
  touch "$TREE/$(cat "$MUT_DIR/mutated")"
  rm -f "$MUT_DIR/mutated"
fi
if [[ ! -f $BUILD/CMakeCache.txt ]]; then
  cmake -S "$TREE" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER_LAUNCHER=ccache \
    > "$MUT_DIR/configure.log" 2>&1 || { echo "configure failed: $MUT_DIR/configure.log"; exit 1; }
fi
build() { cmake --build "$BUILD" -j"$JOBS" --target vshell "${BINARIES[@]}" > "$MUT_DIR/build.log" 2>&1; }

# The test binaries' checksums, one line each.
checksums() { (cd "$BUILD/tests" && sha256sum "${BINARIES[@]}"); }

# Runs the binaries named (default: all; two at a time); prints the failed tests, one per line.
run_tests() {
  local out=$MUT_DIR/out b
  local run=("$@") extra=() started=() failed_one=0
  [[ ${#run[@]} -eq 0 ]] && run=("${BINARIES[@]}")
  [[ $FAIL_FAST == 1 ]] && extra=(--gtest_fail_fast)
  rm -rf "$out"
  mkdir -p "$out"
  running() {
    local n=0 s
    for s in "${started[@]}"; do [[ -f $out/$s.rc ]] || n=$((n + 1)); done
    echo $n
  }
  any_failed() {
    local s
    for s in "${started[@]}"; do [[ -f $out/$s.rc && $(cat "$out/$s.rc") != 0 ]] && return 0; done
    return 1
  }
  for b in "${run[@]}"; do
    [[ $FAIL_FAST == 1 ]] && any_failed && break
    (
      cd "$BUILD/tests" || exit 1
      timeout "$TIMEOUT" "./$b" --gtest_filter="${FILTER:--$SLOW}" "${extra[@]}" > "$out/$b.log" 2>&1 &
      echo $! > "$out/$b.pid"
      wait $!
      echo $? > "$out/$b.rc"
    ) &
    started+=("$b")
    while [[ ! -f $out/$b.pid ]]; do sleep 0.1; done
    while [[ $(running) -ge 2 ]]; do
      sleep 1
      [[ $FAIL_FAST == 1 ]] && any_failed && break
    done
  done
  while [[ $(running) -gt 0 ]]; do
    if [[ $FAIL_FAST == 1 && $failed_one == 0 ]] && any_failed; then
      failed_one=1
      for b in "${started[@]}"; do
        [[ -f $out/$b.rc ]] || { touch "$out/$b.stopped"; kill "$(cat "$out/$b.pid")" 2> /dev/null; }
      done
    fi
    sleep 1
  done
  wait
  for b in "${started[@]}"; do
    grep -h '^\[  FAILED  \] [A-Za-z].*\.' "$out/$b.log" | sed 's/^\[  FAILED  \] //; s/ .*//; s/,$//' | sort -u
    [[ -f $out/$b.stopped ]] && continue
    local rc
    rc=$(cat "$out/$b.rc")
    [[ $rc == 124 ]] && echo "$b:TIMEOUT"
    if [[ $rc != 0 && $rc != 1 && $rc != 124 ]]; then echo "$b:CRASH($rc)"; fi
  done
}

echo "building the unmutated scratch tree..."
build || { echo "the unmutated tree does not build: $MUT_DIR/build.log"; exit 1; }
echo "baseline tests..."
t0=$(date +%s)
baseline=$(run_tests)
if [[ -n $baseline ]]; then
  echo "the unmutated tree fails tests (fix them first):"
  echo "$baseline"
  exit 1
fi
echo "baseline passed ($(($(date +%s) - t0)) s; load: $(cut -d' ' -f1-3 /proc/loadavg))"
checksums > "$MUT_DIR/baseline.sha256"

total=0
killed=0
survivors=()
table=$MUT_DIR/kill-table.md
echo "| mutation | file | killed by |" > "$table"
echo "|---|---|---|" >> "$table"
while IFS='|' read -r name file old new what; do
  [[ -z $name ]] && continue
  wanted "$name" || continue
  total=$((total + 1))
  cp "$TREE/$file" "$MUT_DIR/saved"
  echo "$file" > "$MUT_DIR/mutated"
  if ! replace "$TREE/$file" "$old" "$new"; then
    echo "$name: NOT APPLIED (the code moved: update the list)"
    survivors+=("$name(not applied)")
    continue
  fi
  t0=$(date +%s)
  changed=()
  if build; then
    for b in "${BINARIES[@]}"; do
      if [[ $ALL_BINARIES == 1 ]] || ! (cd "$BUILD/tests" && grep " $b\$" "$MUT_DIR/baseline.sha256" |
        sha256sum --check --status); then
        changed+=("$b")
      fi
    done
    if [[ ${#changed[@]} -gt 0 ]]; then failed=$(run_tests "${changed[@]}"); else failed=""; fi
  else
    failed="(build failed)"
  fi
  cp "$MUT_DIR/saved" "$TREE/$file"
  touch "$TREE/$file"
  rm -f "$MUT_DIR/mutated"
  t1=$(date +%s)
  if [[ -n $failed ]]; then
    killed=$((killed + 1))
    tests=$(echo "$failed" | paste -sd' ' -)
    echo "KILLED   $name ($what; $((t1 - t0)) s; ran ${changed[*]:-}): $tests"
    echo "| $name: $what | \`$file\` | $(echo "$failed" | paste -sd',' - | sed 's/,/, /g') |" >> "$table"
  else
    survivors+=("$name")
    echo "SURVIVED $name ($what; $((t1 - t0)) s; ran ${changed[*]:-})"
    echo "| $name: $what | \`$file\` | **survived** |" >> "$table"
  fi
done <<< "$MUTATIONS"
build > /dev/null 2>&1  # leave the scratch build unmutated

echo
echo "killed $killed of $total"
[[ ${#survivors[@]} -gt 0 ]] && echo "survived: ${survivors[*]}"
echo "kill table: $table"
[[ $killed -eq $total ]]
