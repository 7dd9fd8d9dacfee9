"""Issue 8's time-to-solution table from the runs of tools/bench_250k_to_1s.sh, side by side: for
each run directory the particles, the simulated time reached and the status, steps, wall time,
particle-steps/s, the front criterion (tools/front_error.py: the fitted shift, the error after it
and unshifted), the linear solver's iterations, the largest shares of the step, and bytes per
particle. A run that spans several output directories (a first segment kept apart) is given as
DIR1+DIR2: the wall times and profiles add, the last directory holds the state.

    /usr/bin/python3 tools/report_250k.py OUT_WCSPH OUT_MPS OUT_ISPH [--shares 5]

Prints a Markdown table (docs/benchmarks.md, "Time to t = 1 s at 255k particles").
"""
import argparse
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
BYTES = ("columns", "neighbour_list", "pressure_matrix", "pressure_preconditioner", "pressure_krylov_vectors")


def load(spec):
    dirs = spec.split("+")
    for d in dirs:
        for name in ("summary.json", "profile.json"):
            if not os.path.isfile(os.path.join(d, name)):
                sys.exit(f"report_250k.py: {d}: no {name} (not a finished or interrupted run)")
    summaries = [json.load(open(os.path.join(d, "summary.json"))) for d in dirs]
    profiles = [json.load(open(os.path.join(d, "profile.json"))) for d in dirs]
    totals = {}
    for p in profiles:
        for e in p["systems"]:
            calls, seconds = totals.get(e["name"], (0, 0.0))
            totals[e["name"]] = (calls + e["calls"], seconds + e["total_s"])
    return dirs[-1], summaries, totals


def front(run_dir):
    out = subprocess.run([sys.executable, os.path.join(HERE, "front_error.py"), run_dir],
                         capture_output=True, text=True)
    if out.returncode != 0:
        return None
    return dict(kv.split("=") for kv in out.stdout.split())


def row(spec, shares):
    last, summaries, totals = load(spec)
    s = summaries[-1]
    wall = sum(x["wall_time_s"] for x in summaries)
    accounted = sum(t for _, t in totals.values())
    top = sorted(totals.items(), key=lambda kv: -kv[1][1])[:shares]
    shares_text = ", ".join(f"{n} {100 * t / accounted:.0f}% ({1000 * t / max(c, 1):.0f} ms)" for n, (c, t) in top)
    f = front(last)
    front_text = f"{f['shift']}, {f['error']} ({f['unshifted']})" if f else "n/a"
    solver = s.get("linear_solver")
    # The solver statistics of a resumed run count its last segment only (docs/output.md).
    solver_text = (f"{solver['krylov']} + {solver['preconditioner']}: {solver['mean_iterations']:.1f} mean, "
                   f"{solver['max_iterations']} max" if solver else "explicit")
    b = s["bytes_per_particle"]
    bytes_text = " + ".join(f"{b[k]:.0f}" for k in BYTES if k in b) + f" = {sum(b.get(k, 0) for k in BYTES):.0f}"
    return (f"| {s['method']} | {s['fluid_particles']:,} + {s['wall_particles']:,} | {s['simulated_time']:.4g} s, "
            f"{s['status']} | {s['steps']:,} | {wall:,.0f} s ({wall / 3600:.2f} h) | "
            f"{s['particles'] * s['steps'] / wall:.3g} | {front_text} | {solver_text} | {shares_text} | {bytes_text} |")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("runs", nargs="+", help="output directories of tools/bench_250k_to_1s.sh (DIR1+DIR2 adds segments)")
    ap.add_argument("--shares", type=int, default=5, help="how many systems' shares to list")
    args = ap.parse_args()
    print("| method | particles (fluid + wall) | reached | steps | wall time | particle-steps/s | "
          "front: shift, error after (unshifted) | linear solver, iterations per solve (last segment) | "
          "largest shares (ms per call) | bytes per particle (columns + list [+ matrix + preconditioner + Krylov]) |")
    print("|" + "---|" * 10)
    for spec in args.runs:
        print(row(spec, args.shares))


if __name__ == "__main__":
    main()
