#!/bin/bash
# Time vshell on ex4b at divisions 16 and 8 (the compare_shell.sh settings, rigid-plastic), on one
# thread (as ccx) and on the default threads: appends to results/vshell_times_threads.csv.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
vshell=${1:-$root/build/app/vshell}
out=$here/results/vshell_times_threads.csv
[ -f "$out" ] || echo "divisions,omp_threads,wall_s,cpu_user_s,load_1min_start" > "$out"
for n in 16 8; do
  for th in 1 default; do
    load=$(cut -d' ' -f1 /proc/loadavg)
    tf=$(mktemp)
    if [ "$th" = 1 ]; then env=(OMP_NUM_THREADS=1); else env=(); fi
    env "${env[@]}" /usr/bin/time -f "%e %U" -o "$tf" "$vshell" run "$root/data/scenes/ex4b_square_clamped.toml" \
      --set blank.divisions=$n --set numerics.time_integration=implicit --set numerics.start_refinement=0 \
      --set numerics.max_travel_increment_per_length=0.25 --set numerics.contact_events=false \
      --set numerics.max_travel_increment_mm=0.5 \
      -o "$(mktemp -d)" > /dev/null 2>&1
    read -r wall user < "$tf"; rm -f "$tf"
    echo "$n,$th,$wall,$user,$load" >> "$out"
  done
done
cat "$out"
