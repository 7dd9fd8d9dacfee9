#!/usr/bin/env bash
# ISPH at >= 250k particles (issue 8's benchmark): the violent-flow dam break
# (scenes/dam_break_isph_2d.toml, a/d = 357, 1 m walls as in tools/bench_dam_break.sh), 2 threads,
# a fixed number of steps from the start, once with BiCGSTAB + the bucket multigrid and once with
# BiCGSTAB + Jacobi (iteration cap raised to 50,000: Jacobi needs thousands here): the per-system table, mean and max iterations per solve, whole-step
# particle-steps/s and bytes per particle of each, and the whole-step speed-up.
# Usage: tools/bench_isph.sh [BUILD_DIR] [STEPS]
set -euo pipefail
build=${1:-build}
steps=${2:-20}
declare -A rate
for pc in multigrid jacobi; do
  out=$(mktemp -d)
  echo "== BiCGSTAB + $pc, $steps steps"
  "$build/ryushi" run scenes/dam_break_isph_2d.toml --out "$out" --threads 2 --set 'wall.0.max=[1.0, 1.0]' \
    --set particles.spacing=0.0007 --set time.max_steps="$steps" --set output.interval=100 \
    --set solver.preconditioner="\"$pc\"" --set solver.max_iterations=50000 2>&1 | sed -n '/^system /,/^reorder_by_cell/p'
  rate[$pc]=$(/usr/bin/python3 -c "
import json; s = json.load(open('$out/summary.json')); l = s['linear_solver']; b = s['bytes_per_particle']
print('%.4g' % s['particle_steps_per_second'])
import sys; parts = ('columns', 'neighbour_list', 'pressure_matrix', 'pressure_preconditioner', 'pressure_krylov_vectors')
print('particles %d, steps %d, mean iterations %.1f, max %d, bytes/particle: %s = %.0f'
  % (s['particles'], s['steps'], l['mean_iterations'], l['max_iterations'],
     ' + '.join('%s %.0f' % (k, b[k]) for k in parts if k in b), sum(b.get(k, 0) for k in parts)), file=sys.stderr)")
  echo "particle-steps/s ${rate[$pc]}"
  rm -rf "$out"
done
/usr/bin/python3 -c "print('whole-step speed-up, multigrid over Jacobi: %.2fx' % (${rate[multigrid]} / ${rate[jacobi]}))"
