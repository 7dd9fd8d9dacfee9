#!/usr/bin/python3
"""Speed against accuracy of the operators, from the CSV of build/bench/ryushi_bench_operators.

Usage: /usr/bin/python3 tools/plot_operators.py operators.csv docs/img/operators_speed_accuracy.png
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def main():
    data = np.genfromtxt(sys.argv[1], delimiter=",", names=True, dtype=None, encoding="utf-8")
    fig, axes = plt.subplots(1, 2, figsize=(12, 5))
    for ax, dim in zip(axes, (2, 3)):
        rows = data[data["dim"] == dim]
        for row in rows:
            ax.scatter(row["ns_per_particle"], row["rmse_regular"], marker="o", color="C0")
            ax.scatter(row["ns_per_particle"], row["rmse_disordered"], marker="x", color="C3")
            ax.annotate(row["operator"], (row["ns_per_particle"], row["rmse_regular"]), fontsize=7,
                        xytext=(3, 3), textcoords="offset points")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("ns per particle (1e6 particles, 2 threads)")
        ax.set_ylabel("RMSE, interior (%s)" % ("d = 1/80" if dim == 2 else "d = 1/40"))
        ax.set_title("%dD: o regular, x 20%% disorder" % dim)
        ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=110)


if __name__ == "__main__":
    main()
