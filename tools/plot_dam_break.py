#!/usr/bin/python3
"""Surge front of a dam-break run against Martin & Moyce (1952), as a PNG.

Usage: /usr/bin/python3 tools/plot_dam_break.py OUT_DIR PNG [a]
OUT_DIR is a run of scenes/dam_break_2d.toml (its probes.csv); a is the column width (0.25 m).
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def main():
    out, png = sys.argv[1], sys.argv[2]
    a = float(sys.argv[3]) if len(sys.argv) > 3 else 0.25
    g = 9.81
    run = np.genfromtxt(os.path.join(out, "probes.csv"), delimiter=",", names=True)
    here = os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(here, "reference", "martin_moyce_1952_n2_2.csv")) as f:
        lines = [l for l in f if l.strip() and not l.startswith("#")]
    ref = np.genfromtxt(lines, delimiter=",", names=True)
    T = run["time"] * np.sqrt(2 * g / a)
    Z = run["surge_front"] / a
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(T, Z, "-", label="ryushi WCSPH")
    ax.plot(T + 0.2, Z, "--", label="ryushi, time origin shifted by 0.2")
    ax.plot(ref["T"], ref["Z"], "o", label="Martin & Moyce 1952 (n$^2$ = 2)")
    ax.set_xlabel("T = t sqrt(2g/a)")
    ax.set_ylabel("Z = x/a")
    ax.set_xlim(0, 4)
    ax.set_ylim(1, 4.2)
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(png, dpi=120)


if __name__ == "__main__":
    main()
