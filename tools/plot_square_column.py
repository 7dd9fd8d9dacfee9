#!/usr/bin/python3
"""Martin & Moyce's square column (n^2 = 1): the surge front and the water's height at the back
wall of one or more runs against the experiment (tools/reference/martin_moyce_1952_square*.csv),
as one PNG of two panels, T = t sqrt(g/a).

Usage: /usr/bin/python3 tools/plot_square_column.py PNG LABEL=OUT_DIR [LABEL=OUT_DIR ...] [--a 0.25]
Each OUT_DIR is a run with probes `surge_front` and `height_left_wall` (scenes/dam_break_square_2d.toml,
or a dam-break scene with the square column: docs/validation.md, "The square column").
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))


def table(name):
    with open(os.path.join(HERE, "reference", name)) as f:
        lines = [l for l in f if l.strip() and not l.startswith("#")]
    return np.genfromtxt(lines, delimiter=",", names=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("png")
    ap.add_argument("runs", nargs="+", help="LABEL=OUT_DIR")
    ap.add_argument("--a", type=float, default=0.25)
    args = ap.parse_args()
    g = 9.81
    front, height = table("martin_moyce_1952_square.csv"), table("martin_moyce_1952_square_height.csv")
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4))
    for spec in args.runs:
        label, out = spec.split("=", 1)
        run = np.genfromtxt(os.path.join(out, "probes.csv"), delimiter=",", names=True)
        T = run["time"] * np.sqrt(g / args.a)
        left.plot(T, run["surge_front"] / args.a, "-", label=label)
        right.plot(T, run["height_left_wall"] / args.a, "-", label=label)
    left.plot(front["T"], front["Z"], "ko", label="Martin & Moyce (square column)")
    right.plot(height["T"], height["H"], "ko", label="Martin & Moyce (square column)")
    left.set_xlabel("T = t sqrt(g/a)")
    left.set_ylabel("front Z = x/a")
    right.set_xlabel("T = t sqrt(g/a)")
    right.set_ylabel("height at the back wall H = h/a")
    right.set_xlim(0, 7)
    for ax in (left, right):
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.png, dpi=110)


if __name__ == "__main__":
    main()
