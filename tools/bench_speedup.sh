#!/usr/bin/env bash
# Old binary against new, side by side in one sitting (issue 13): builds ryushi at BASE (default
# 15b7305, the commit before the speed work) into build-base/, then alternates the two binaries
# on the 2D WCSPH dam break of tools/bench_dam_break.sh (267,777 particles, 2 threads) and prints
# each run's particle-steps/s, the medians and their ratio, and the per-system table of the last
# run of each. Alternating spreads any drift of a shared machine over both. Two cases: the dam
# break from rest (the benchmark's usual start: particles barely move, so a Verlet list is almost
# never rebuilt) and the same block moving at 3 m/s, about the dam break's peak speed, which
# rebuilds a Verlet list as often as the real flow does. Each binary reads its own tree's scene
# (the old one cannot parse the keys added since). The new binary runs twice: with its default
# integrator (the leapfrog since 2026-11-24: one force evaluation per step) and with the midpoint
# (the old binary's algorithm, so that ratio is the speed work alone).
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

run() {  # binary, scene, output dir, block velocity, [extra --set]: prints particle-steps/s; keeps the log
  "$1" run "$2" --out "$3" --threads 2 --set 'wall.0.max=[1.0, 1.0]' \
    --set particles.spacing=0.0007 --set time.max_steps="$steps" --set output.interval=100 \
    --set "fluid.0.velocity=[$4, 0.0]" ${5:+--set "$5"} >"$3.log" 2>&1
  sed -n 's/.*"particle_steps_per_second": \([0-9.e+]*\).*/\1/p' "$3/summary.json"
}
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
out=$(mktemp -d)
for speed in 0.0 3.0; do
  echo "== block velocity $speed m/s, $steps steps, $repeats repeats"
  old_rates=() mid_rates=() new_rates=()
  for r in $(seq "$repeats"); do
    old_rates+=("$(run build-base/build/ryushi "$tree/scenes/dam_break_2d.toml" "$out/old$r" "$speed")")
    mid_rates+=("$(run "$new/ryushi" scenes/dam_break_2d.toml "$out/mid$r" "$speed" method.integrator=midpoint)")
    new_rates+=("$(run "$new/ryushi" scenes/dam_break_2d.toml "$out/new$r" "$speed")")
    echo "repeat $r: old ${old_rates[-1]}  new midpoint ${mid_rates[-1]}  new default ${new_rates[-1]} particle-steps/s"
  done
  mo=$(median "${old_rates[@]}") mm=$(median "${mid_rates[@]}") mn=$(median "${new_rates[@]}")
  echo "old ($base), last repeat:"
  grep -m1 '^system' -A6 "$out/old$repeats.log" | sed 's/^/  /'
  echo "new midpoint, last repeat ($(sed -n 's/.*"neighbour_list_builds": \([0-9]*\).*/\1/p' "$out/mid$repeats/summary.json") neighbour-list builds):"
  grep -m1 '^system' -A6 "$out/mid$repeats.log" | sed 's/^/  /'
  echo "new default, last repeat ($(sed -n 's/.*"neighbour_list_builds": \([0-9]*\).*/\1/p' "$out/new$repeats/summary.json") neighbour-list builds):"
  grep -m1 '^system' -A6 "$out/new$repeats.log" | sed 's/^/  /'
  awk -v o="$mo" -v m="$mm" -v n="$mn" -v b="$base" -v s="$speed" 'BEGIN {printf "block at %s m/s: median particle-steps/s old (%s) %.3g, new midpoint %.3g (ratio %.2f), new default %.3g (ratio %.2f)\n", s, b, o, m, m / o, n, n / o}'
done
rm -rf "$out"
