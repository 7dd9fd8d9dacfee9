#!/usr/bin/env bash
# Throughput benchmark of the 2D dam break at >= 250k particles (a/d = 357), 2 threads, fixed
# number of steps. Prints the profile table and the summary lines (particle-steps/s, bytes per
# particle). Usage: tools/bench_dam_break.sh [BUILD_DIR] [STEPS]
set -euo pipefail
build=${1:-build}
steps=${2:-40}
out=$(mktemp -d)
# 1 m walls as when the figures in docs/benchmarks.md were taken (267,777 particles): the scene's
# 2.5 m walls, there for the run-up jet of long runs, would add 12,860 wall particles.
"$build/ryushi" run scenes/dam_break_2d.toml --out "$out" --threads 2 --set 'wall.0.max=[1.0, 1.0]' \
  --set particles.spacing=0.0007 --set time.max_steps="$steps" --set output.interval=100
grep -E '"particles"|"steps"|"wall_time_s"|"particle_steps_per_second"|"columns"|"neighbour_list"' "$out/summary.json"
rm -rf "$out"
