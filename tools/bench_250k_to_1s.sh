#!/usr/bin/env bash
# Issue 8's time to solution at scale: the Martin & Moyce dam break (a = 0.25 m, n^2 = 2, each
# method's own scene and walls) at a/d = 357 (about 255k fluid particles) run to t = 1 s on 2
# threads, checkpointed every 0.05 s so that a run stopped part-way continues where it was (run
# the same command again: it resumes; the wall time and the profile add up over the segments).
# Prints the particles, steps, wall time, particle-steps/s, the per-system shares, the linear
# solver's iterations (of the last segment) and the front error of tests/front_criterion.hpp.
# A run takes hours (docs/benchmarks.md, "Time to t = 1 s at 255k particles"): give it the
# machine alone, its wall time is the measurement.
# Usage: tools/bench_250k_to_1s.sh [BUILD_DIR] METHOD [OUT_DIR]     METHOD: wcsph | mps | isph
set -euo pipefail
build=${1:-build}
method=${2:?method: wcsph, mps or isph}
out=${3:-out/bench_250k_$method}
declare -A scene=([wcsph]=dam_break_2d.toml [mps]=dam_break_mps_2d.toml [isph]=dam_break_isph_2d.toml)
[ -n "${scene[$method]:-}" ] || { echo "unknown method '$method'" >&2; exit 2; }
# Where the run stands (simulated time, steps, wall time, status) from its summary.json, for the
# segment log: a run that spans sittings keeps in OUT/segments.csv which binary ran which part.
state() {
  /usr/bin/python3 -c "
import json, sys
try:
    s = json.load(open('$out/summary.json'))
    print('%.6g,%d,%.1f,%s' % (s['simulated_time'], s['steps'], s['wall_time_s'], s['status']))
except OSError:
    print('0,0,0,none')"
}
mkdir -p "$out"
[ -f "$out/segments.csv" ] || echo "started,ended,binary_md5,t_from,steps_from,wall_from,status_from,t_to,steps_to,wall_to,status_to" > "$out/segments.csv"
started=$(date -u +%FT%TZ) before=$(state)
if [ -f "$out/checkpoint.h5" ] && ! grep -q '"status": "completed"' "$out/summary.json" 2>/dev/null; then
  "$build/ryushi" resume "$out" --threads 2
elif [ ! -f "$out/summary.json" ] || ! grep -q '"status": "completed"' "$out/summary.json"; then
  "$build/ryushi" run "scenes/${scene[$method]}" --out "$out" --overwrite --threads 2 --set particles.spacing=0.0007 \
    --set time.end=1.0 --set output.interval=0.25 --set output.probe_interval=0.002 --checkpoint-interval 0.05
fi || true  # an interrupted segment (exit 130) is logged and reported like a finished one
echo "$started,$(date -u +%FT%TZ),$(md5sum "$build/ryushi" | cut -c1-12),$before,$(state)" >> "$out/segments.csv"
/usr/bin/python3 - "$out" <<'PY'
import json, sys
out = sys.argv[1]
s = json.load(open(out + '/summary.json')); p = json.load(open(out + '/profile.json'))
print('%s: %d particles (%d fluid), %d steps to t = %.4g s, wall %.1f s, %.3g particle-steps/s, %s'
      % (s['method'], s['particles'], s['fluid_particles'], s['steps'], s['simulated_time'], s['wall_time_s'],
         s['particle_steps_per_second'], s['status']))
for e in sorted(p['systems'], key=lambda e: -e['total_s'])[:10]:
    print('  %-28s %5.1f%%  %8.2f ms per call' % (e['name'], 100 * e['share'], 1000 * e['mean_s']))
if 'linear_solver' in s:
    l = s['linear_solver']
    print('  linear solver: %s + %s, mean %.1f / max %d iterations per solve' % (l['krylov'], l['preconditioner'], l['mean_iterations'], l['max_iterations']))
PY
echo "front: $(/usr/bin/python3 tools/front_error.py "$out")"
