"""Two ryushi binaries side by side on one scene, alternating (old, new, old, new, ...) so that the
drift of a shared machine falls on both: prints each run's wall time, then per system the median
ms per step of each binary and their ratio, and the whole step's ratio.

    /usr/bin/python3 tools/bench_ab.py OLD_BINARY NEW_BINARY SCENE [--repeats 3] [--threads 2]
        [--set key=value ...] [--old-scene OLD_SCENE]

--old-scene gives the old binary its own tree's scene (an old binary cannot parse keys added
since; the new scene's defaults may differ too: say so when you report the ratio). The last
lines give the whole step (wall time per step, start-up included) and the sum of the systems
without output (frames written are not the step's physics; a short run's first frame weighs).

e.g. the ISPH dam break at a/d = 100 for 0.05 s:
    /usr/bin/python3 tools/bench_ab.py build-prev/build/ryushi build/ryushi \\
        scenes/dam_break_isph_2d.toml --set particles.spacing=0.0025 --set time.end=0.05
Both binaries must take the same steps (same algorithm): the script says so if they do not.
"""
import argparse
import json
import os
import statistics
import shutil
import subprocess
import tempfile


def run(binary, scene, sets, threads, out):
    cmd = [binary, "run", scene, "--out", out, "--threads", str(threads), "--quiet", "--set", "output.interval=1e9"]
    for s in sets:
        cmd += ["--set", s]
    shutil.rmtree(out, ignore_errors=True)  # a run refuses a directory with another run's files
    subprocess.run(cmd, check=True)
    summary = json.load(open(os.path.join(out, "summary.json")))
    profile = json.load(open(os.path.join(out, "profile.json")))
    steps = summary["steps"]
    per_system = {s["name"]: 1e3 * s["total_s"] / steps for s in profile["systems"]}
    return summary["wall_time_s"], steps, summary["particles"], per_system


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("scene")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--set", action="append", default=[])
    ap.add_argument("--old-scene", default=None)
    args = ap.parse_args()
    results = {"old": [], "new": []}
    with tempfile.TemporaryDirectory() as tmp:
        for r in range(args.repeats):
            for which in ("old", "new"):
                binary = getattr(args, which)
                scene = args.old_scene if which == "old" and args.old_scene else args.scene
                res = run(binary, scene, args.set, args.threads, os.path.join(tmp, f"{which}{r}"))
                results[which].append(res)
                print(f"repeat {r + 1} {which}: {res[0]:.2f} s, {res[1]} steps")
    steps = {results[w][0][1] for w in results}
    if len(steps) != 1:
        print(f"note: the binaries took different numbers of steps {sorted(steps)}; ms per step compared")
    names = sorted(set(results["old"][0][3]) | set(results["new"][0][3]),
                   key=lambda n: -statistics.median(r[3].get(n, 0) for r in results["old"]))
    print(f"{'system (median ms/step)':32s} {'old':>9s} {'new':>9s} {'old/new':>8s}")
    for n in names:
        o = statistics.median(r[3].get(n, 0) for r in results["old"])
        w = statistics.median(r[3].get(n, 0) for r in results["new"])
        if o < 0.005 and w < 0.005:
            continue
        print(f"{n:32s} {o:9.3f} {w:9.3f} {o / w if w > 0 else float('inf'):8.2f}")
    o = statistics.median(1e3 * r[0] / r[1] for r in results["old"])
    w = statistics.median(1e3 * r[0] / r[1] for r in results["new"])
    particles = results["new"][0][2]
    print(f"{'whole step':32s} {o:9.3f} {w:9.3f} {o / w:8.2f}")
    so = statistics.median(sum(v for k, v in r[3].items() if k != "output") for r in results["old"])
    sw = statistics.median(sum(v for k, v in r[3].items() if k != "output") for r in results["new"])
    print(f"{'systems without output':32s} {so:9.3f} {sw:9.3f} {so / sw:8.2f}")
    print(f"particle-steps/s: old {particles / o * 1e3:.3g}, new {particles / w * 1e3:.3g} ({particles} particles)")


if __name__ == "__main__":
    main()
