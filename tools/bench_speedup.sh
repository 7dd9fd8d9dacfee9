#!/usr/bin/env bash
# Old binary against new, side by side in one sitting (issue 13): builds ryushi at BASE (default
# 15b7305, the commit before the speed work) into build-base/, then alternates the two binaries
# on the 2D WCSPH dam break of tools/bench_dam_break.sh (267,777 particles, 2 threads) and prints
# each run's particle-steps/s, the medians and their ratio, and the per-system table of the last
# run of each. Alternating spreads any drift of a shared machine over both.
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

run() {  # binary, output dir: prints particle-steps/s; keeps the log
  "$1" run scenes/dam_break_2d.toml --out "$2" --threads 2 --set 'wall.0.max=[1.0, 1.0]' \
    --set particles.spacing=0.0007 --set time.max_steps="$steps" --set output.interval=100 >"$2.log" 2>&1
  sed -n 's/.*"particle_steps_per_second": \([0-9.e+]*\).*/\1/p' "$2/summary.json"
}
out=$(mktemp -d)
old_rates=() new_rates=()
for r in $(seq "$repeats"); do
  old_rates+=("$(run build-base/build/ryushi "$out/old$r")")
  new_rates+=("$(run "$new/ryushi" "$out/new$r")")
  echo "repeat $r: old ${old_rates[-1]}  new ${new_rates[-1]} particle-steps/s"
done
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
mo=$(median "${old_rates[@]}") mn=$(median "${new_rates[@]}")
echo "old ($base): $(grep -m1 '^system' -A12 "$out/old$repeats.log" | sed 's/^/  /')"
echo "new: $(grep -m1 '^system' -A12 "$out/new$repeats.log" | sed 's/^/  /')"
awk -v o="$mo" -v n="$mn" -v b="$base" 'BEGIN {printf "median particle-steps/s: old (%s) %.3g, new %.3g, ratio %.2f\n", b, o, n, n / o}'
rm -rf "$out"
