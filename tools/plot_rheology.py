"""Velocity profiles of the non-Newtonian Poiseuille scenes against their analytic steady ones.

    /usr/bin/python3 tools/plot_rheology.py OUT.png POWER_LAW_0.5_RUN POWER_LAW_1.5_RUN BINGHAM_RUN

The runs are scenes/poiseuille_power_law_2d.toml (n = 0.5 as shipped; n = 1.5 with
--set material.power_index=1.5 --set physics.gravity=[0.01,0.0]) and
scenes/poiseuille_bingham_2d.toml; each run's last frame is drawn (u against y, the particles
as dots) over the analytic profile of tests/rheology_test.cpp, with the L2 error relative to the
largest speed in the legend. Exit codes: 0 done, 2 bad input.
"""
import glob
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

B, RHO = 5e-4, 1000.0


def power_law(K, n, F):
    return lambda y: n / (n + 1) * (RHO * F / K) ** (1 / n) * (B ** ((n + 1) / n) - np.abs(y) ** ((n + 1) / n))


def bingham(mu, tau0, F):
    def u(y):
        yc = np.maximum(np.abs(y), tau0 / (RHO * F))
        return (RHO * F / 2 * (B * B - yc * yc) - tau0 * (B - yc)) / mu
    return u


def last_frame(run):
    frames = sorted(glob.glob(os.path.join(run, "frames", "frame_*.h5")))
    if not frames:
        sys.exit(f"plot_rheology: no frames in {run}")
    return frames[-1]


def main():
    if len(sys.argv) != 5:
        print(__doc__)
        sys.exit(2)
    cases = [("power law n = 0.5", power_law(0.01, 0.5, 0.03)), ("power law n = 1.5", power_law(0.01, 1.5, 0.01)),
             ("Bingham, plug |y| < 0.3 b", bingham(0.01, 0.0045, 0.03))]
    fig, axes = plt.subplots(1, 3, figsize=(12, 4))
    for ax, run, (title, exact) in zip(axes, sys.argv[2:], cases):
        with h5py.File(last_frame(run), "r") as f:
            fluid = f["kind"][:] == 0
            y = f["position"][:][fluid, 1] - B
            u = f["velocity"][:][fluid, 0]
            t = f.attrs["time"]
        e = np.sqrt(np.mean((u - exact(y)) ** 2)) / exact(0.0)
        ys = np.linspace(-B, B, 401)
        ax.plot(exact(ys) * 1e3, ys * 1e3, "k-", label="analytic")
        ax.plot(u * 1e3, y * 1e3, ".", ms=3, label=f"ryushi t = {t:.2f} s, L2 {100 * e:.2f}%")
        ax.set_title(title)
        ax.set_xlabel("u (mm/s)")
        ax.set_ylabel("y from the middle (mm)")
        ax.legend(fontsize=8, loc="lower left")
    fig.tight_layout()
    fig.savefig(sys.argv[1], dpi=100)
    print(sys.argv[1])


if __name__ == "__main__":
    main()
