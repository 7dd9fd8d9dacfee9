#!/usr/bin/env bash
# Time to solution, method against method, in one sitting: the Martin & Moyce dam break (a = 0.25
# m, n^2 = 2) at one resolution to T = t sqrt(2g/a), each method's own scene, 2 threads; the wall
# time, steps, particle-steps/s and the front error of tests/front_criterion.hpp (fitted shift,
# error after it, unshifted error) per method.
# Usage: tools/bench_time_to_solution.sh [BUILD_DIR] [A_OVER_D] [T_END] [METHODS...]
#   e.g. tools/bench_time_to_solution.sh build 100 2.5 isph mps wcsph
set -euo pipefail
build=${1:-build}
ratio=${2:-100}
T_end=${3:-2.5}
methods=("${@:4}")
[ ${#methods[@]} -eq 0 ] && methods=(isph mps wcsph)
spacing=$(/usr/bin/python3 -c "print(0.25 / $ratio)")
end=$(/usr/bin/python3 -c "import math; print($T_end * math.sqrt(0.25 / (2 * 9.81)) + 1e-9)")
declare -A scene=([wcsph]=dam_break_2d.toml [mps]=dam_break_mps_2d.toml [isph]=dam_break_isph_2d.toml)
printf '%-6s %9s %7s %9s %14s  %s\n' method particles steps wall_s particle-steps/s "front (tests/front_criterion.hpp)"
for m in "${methods[@]}"; do
  out=$(mktemp -d)
  "$build/ryushi" run "scenes/${scene[$m]}" --out "$out" --threads 2 --quiet --set particles.spacing="$spacing" \
    --set time.end="$end" --set output.interval=100 --set output.probe_interval=0.002
  read -r particles steps wall rate < <(/usr/bin/python3 -c "
import json; s = json.load(open('$out/summary.json'))
print(s['particles'], s['steps'], round(s['wall_time_s'], 1), '%.3g' % s['particle_steps_per_second'])")
  printf '%-6s %9s %7s %9s %14s  %s\n' "$m" "$particles" "$steps" "$wall" "$rate" "$(/usr/bin/python3 tools/front_error.py "$out")"
  rm -rf "$out"
done
