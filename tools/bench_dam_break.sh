#!/usr/bin/env bash
# Throughput benchmark of the 2D dam break at >= 250k particles (a/d = 357), 2 threads, fixed
# number of steps. Prints the profile table and the summary lines (particle-steps/s, bytes per
# particle). Usage: tools/bench_dam_break.sh [BUILD_DIR] [STEPS]
set -euo pipefail
build=${1:-build}
steps=${2:-40}
out=$(mktemp -d)
"$build/ryushi" run scenes/dam_break_2d.toml --out "$out" --threads 2 \
  --set particles.spacing=0.0007 --set time.max_steps="$steps" --set output.interval=100
grep -E '"particles"|"steps"|"wall_time_s"|"particle_steps_per_second"|"columns"|"neighbour_list"' "$out/summary.json"
rm -rf "$out"
