#!/usr/bin/env bash
# Wall time per unit of T = t sqrt(2g/a) on the 2D dam break at about 255k particles (a/d = 357,
# 1 m walls as in tools/bench_dam_break.sh), every method (issue 13, goal 6), 2 threads:
#   ms per step      measured here: the first STEPS steps of each method's own dam-break scene at
#                    a/d = 357 (profile.json's step_wall_s: the steps only, not the set-up);
#   steps per unit T counted over a whole run at a/d = 100 to T = 2.5 (tools/bench_time_to_solution.sh,
#                    in this sitting), times 357/100: every method's step is proportional to d
#                    (a velocity CFL for ISPH and MPS, the acoustic CFL at a fixed sound speed for
#                    WCSPH), so the count scales with a/d.
# The product is an estimate (the step's cost grows during a run as the solves get harder and the
# particles disorder): it says which method a user waits for, not the last second.
# Usage: tools/bench_time_per_unit_T.sh [BUILD_DIR] [STEPS] [METHODS...]
set -euo pipefail
build=${1:-build}
steps=${2:-10}
methods=("${@:3}")
[ ${#methods[@]} -eq 0 ] && methods=(wcsph mps isph)
declare -A scene=([wcsph]=dam_break_2d.toml [mps]=dam_break_mps_2d.toml [isph]=dam_break_isph_2d.toml)
counts=$(mktemp)
tools/bench_time_to_solution.sh "$build" 100 2.5 "${methods[@]}" | tee "$counts"
printf '\n%-6s %9s %11s %16s %14s\n' method particles ms/step "steps per unit T" "s per unit T"
for m in "${methods[@]}"; do
  out=$(mktemp -d)
  "$build/ryushi" run "scenes/${scene[$m]}" --out "$out" --threads 2 --quiet --set 'wall.0.max=[1.0, 1.0]' \
    --set particles.spacing=0.0007 --set time.max_steps="$steps" --set output.interval=100 2>/dev/null
  read -r particles ms < <(/usr/bin/python3 -c "
import json; s = json.load(open('$out/summary.json')); p = json.load(open('$out/profile.json'))
print(s['particles'], '%.1f' % (1e3 * p['step_wall_s'] / s['steps']))")
  run_steps=$(awk -v m="$m" '$1 == m {print $3}' "$counts")
  /usr/bin/python3 -c "
per_T = $run_steps / 2.5 * 357 / 100
print('%-6s %9d %11s %16.0f %14.0f' % ('$m', $particles, '$ms', per_T, per_T * $ms / 1e3))"
  rm -rf "$out"
done
rm -f "$counts"
