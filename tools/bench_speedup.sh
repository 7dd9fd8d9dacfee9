#!/usr/bin/env bash
# Old binary against new, side by side in one sitting (issue 13): builds ryushi at BASE (default
# 15b7305, the commit before the speed work) into build-base/, then alternates the two binaries
# on the 2D WCSPH dam break of tools/bench_dam_break.sh (267,777 particles, 2 threads) and prints
# each run's particle-steps/s, the medians and their ratio, and the per-system table of the last
# run of each. Alternating spreads any drift of a shared machine over both. Two cases: the dam
# break from rest (the benchmark's usual start: particles barely move, so a Verlet list is almost
# never rebuilt) and the same block moving at 3 m/s, about the dam break's peak speed, which
# rebuilds a Verlet list as often as the real flow does.
# Usage: tools/bench_speedup.sh [NEW_BUILD_DIR] [STEPS] [REPEATS]
set -euo pipefail
new=${1:-build}
steps=${2:-60}
repeats=${3:-3}
base=${BASE:-15b7305}
tree=build-base/tree
if [ ! -d "$tree" ]; then
  git worktree add --detach "$tree" "$base" >/dev/null
else
  git -C "$tree" checkout -q --detach "$base"
fi
cmake -S "$tree" -B build-base/build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build-base/build --target ryushi -j2 >/dev/null

run() {  # binary, output dir, block velocity: prints particle-steps/s; keeps the log
  "$1" run scenes/dam_break_2d.toml --out "$2" --threads 2 --set 'wall.0.max=[1.0, 1.0]' \
    --set particles.spacing=0.0007 --set time.max_steps="$steps" --set output.interval=100 \
    --set "fluid.0.velocity=[$3, 0.0]" >"$2.log" 2>&1
  sed -n 's/.*"particle_steps_per_second": \([0-9.e+]*\).*/\1/p' "$2/summary.json"
}
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
out=$(mktemp -d)
for speed in 0.0 3.0; do
  echo "== block velocity $speed m/s, $steps steps, $repeats repeats"
  old_rates=() new_rates=()
  for r in $(seq "$repeats"); do
    old_rates+=("$(run build-base/build/ryushi "$out/old$r" "$speed")")
    new_rates+=("$(run "$new/ryushi" "$out/new$r" "$speed")")
    echo "repeat $r: old ${old_rates[-1]}  new ${new_rates[-1]} particle-steps/s"
  done
  mo=$(median "${old_rates[@]}") mn=$(median "${new_rates[@]}")
  echo "old ($base), last repeat:"
  grep -m1 '^system' -A6 "$out/old$repeats.log" | sed 's/^/  /'
  echo "new, last repeat ($(sed -n 's/.*"neighbour_list_builds": \([0-9]*\).*/\1/p' "$out/new$repeats/summary.json") neighbour-list builds):"
  grep -m1 '^system' -A6 "$out/new$repeats.log" | sed 's/^/  /'
  awk -v o="$mo" -v n="$mn" -v b="$base" -v s="$speed" 'BEGIN {printf "block at %s m/s: median particle-steps/s old (%s) %.3g, new %.3g, ratio %.2f\n", s, b, o, n, n / o}'
done
rm -rf "$out"
