#!/usr/bin/python3
"""Speed and accuracy of the shallow-water method on Ritter's dry-bed dam break (docs/swe.md).

Runs scenes/dam_break_ritter_swe.toml at a spacing (default 1/30 m: about 10x the test's 460
particles) with splitting at area_ratio 1.5, 2.0 and 3.0 and without, one after the other in one
sitting, and prints a markdown table: particles at the start and at t = 0.5 s, steps, wall time,
particle-steps per second, the splitting system's share of the step, the front-region depth
error and the front position against the analytic one. With --plot PNG it also draws the depth
profiles at t = 0.5 s against eq. 14 and the particles in the plan view.

    /usr/bin/python3 tools/bench_swe.py [--build build] [--spacing 0.0333333] [--threads 2] [--plot docs/img/swe_ritter.png]
"""
import argparse
import json
import math
import os
import subprocess
import tempfile


def run(binary, spacing, threads, out, extra):
    cmd = [binary, "run", "scenes/dam_break_ritter_swe.toml", "--out", out, "--quiet", "--threads", str(threads),
           "--set", f"particles.spacing={spacing!r}"] + [a for s in extra for a in ("--set", s)]
    subprocess.run(cmd, check=True)
    summary = json.load(open(os.path.join(out, "summary.json")))
    profile = json.load(open(os.path.join(out, "profile.json")))
    share = sum(s["share"] for s in profile["systems"] if s["name"] == "particle_splitting")
    return summary, share


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default="build")
    ap.add_argument("--spacing", type=float, default=1 / 30)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--plot", default="")
    args = ap.parse_args()
    binary = os.path.join(args.build, "ryushi")
    configs = [("split at 1.5 A0", ["splitting.area_ratio=1.5"]), ("split at 2.0 A0", ["splitting.area_ratio=2.0"]),
               ("split at 3.0 A0", ["splitting.area_ratio=3.0"]), ("no splitting", ["splitting.enabled=false"])]
    tmp = tempfile.mkdtemp(prefix="bench_swe_")
    rows, outs = [], []
    for name, extra in configs:
        out = os.path.join(tmp, name.replace(" ", "_").replace(".", ""))
        s, share = run(binary, args.spacing, args.threads, out, extra)
        d = s["diagnostics"]
        outs.append((name, out))
        rows.append((name, s, d, share))
    print(f"Ritter dam break, spacing {args.spacing:.4g} m, to t = 0.5 s, {args.threads} threads\n")
    print("| run | particles start -> end | steps | wall s | particle-steps/s | splitting share | front-region error | wave error | front m (analytic) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name, s, d, share in rows:
        first = s["particles"] - int(d.get("splits", 0))
        print(f"| {name} | {first} -> {s['particles']} | {s['steps']} | {s['wall_time_s']:.3f} | "
              f"{s['particle_steps_per_second']:.3g} | {100 * share:.1f}% | {d['ritter_front_depth_error']:.3f} | "
              f"{d['ritter_depth_error']:.3f} | {d['front_position']:.3f} ({d['ritter_front_position']:.3f}) |")
    if args.plot:
        plot(outs, args.plot)


def plot(outs, png):
    import glob

    import h5py
    import matplotlib
    import numpy as np

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    g, h0, dam = 9.81, 0.25, 4.65
    c0 = math.sqrt(g * h0)
    fig, ax = plt.subplots(3, 1, figsize=(9, 11))
    for name, out in outs:
        last = sorted(glob.glob(os.path.join(out, "frames", "frame_*.h5")))[-1]
        f = h5py.File(last, "r")
        t = float(f.attrs["time"])
        x, h = f["position"][:], f["depth"][:]
        ax[0].plot(x[:, 0], h, ".", ms=2, label=name)
        if name in ("split at 1.5 A0", "no splitting"):
            k = 1 if name.startswith("split") else 2
            ax[k].plot(x[:, 0], x[:, 1], ".", ms=1.5)
            ax[k].set_title(f"{name}: particles at t = {t:g} s")
            ax[k].set_xlim(3.5, 6.5)
            ax[k].set_ylabel("y (m)")
    xs = np.linspace(3.0, 6.5, 600)
    xi = xs - dam
    ha = np.where(xi <= -c0 * t, h0, np.where(xi >= 2 * c0 * t, 0.0, (2 * c0 - xi / t) ** 2 / (9 * g)))
    ax[0].plot(xs, ha, "k-", label="Ritter (eq. 14)")
    ax[0].set_xlim(3.0, 6.5)
    ax[0].set_xlabel("x (m)")
    ax[0].set_ylabel("depth (m)")
    ax[0].set_title(f"Ritter dry-bed dam break at t = {t:g} s")
    ax[0].legend()
    ax[2].set_xlabel("x (m)")
    fig.tight_layout()
    fig.savefig(png, dpi=90)
    print(f"\nwrote {png}")


if __name__ == "__main__":
    main()
