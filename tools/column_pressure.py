#!/usr/bin/env python3
"""The collapsing column's floor pressure in a 2D dam break, from a run's frames.

In every frame: the fluid particles within 0.6 d of x = `--x` (0.1 m: the middle of the 0.25 m
column), those of them below 2 d (the floor's two rows), their mean pressure over rho g times
the height of the water above them (the highest particle there + d/2 minus their mean height).
The column just released holds about a third of that; as it spreads the ratio climbs towards
one (MPS, WCSPH and ISPH agree on it to t = 0.2 s at a/d = 40; docs/isph.md).
Printed as means (with the least and largest frame) over windows of `--window` seconds, so run
with frames close together (`--set output.interval=0.0005`): the ISPH pressure changes from step
to step.

    /usr/bin/python3 tools/column_pressure.py RUN_DIR --spacing 0.0025 [--x 0.1] [--window 0.02]
    /usr/bin/python3 tools/column_pressure.py --plot OUT.png RUN_DIR:FRAME:LABEL ...

--plot draws the fluid's pressure in the named frames side by side (kPa, +-8).
"""
import argparse
import glob
import os

import h5py
import numpy as np

RHO_G = 1000.0 * 9.81


def floor_ratios(run, spacing, x0):
    """(time, floor pressure / rho g height) for every frame of a run."""
    out = []
    for name in sorted(glob.glob(os.path.join(run, "frames", "*.h5"))):
        with h5py.File(name, "r") as f:
            x = f["position"][()][:, :2]
            fluid = f["kind"][()] == 0
            p = f["pressure"][()]
            t = float(f.attrs["time"])
        column = fluid & (np.abs(x[:, 0] - x0) < 0.6 * spacing)
        if not column.any():
            continue
        y, pc = x[column, 1], p[column]
        floor = y < 2 * spacing
        height = y.max() + 0.5 * spacing - y[floor].mean()
        out.append((t, pc[floor].mean() / (RHO_G * height)))
    return np.array(out)


def windows(run, spacing, x0, width):
    series = floor_ratios(run, spacing, x0)
    if len(series) == 0:
        raise SystemExit(f"{run}: no frames with fluid at x = {x0}")
    print(f"{run}: floor pressure / (rho g height) at x = {x0} m, windows of {width} s")
    for start in np.arange(0.0, series[-1, 0] + 1e-12, width):
        inside = (series[:, 0] >= start - 1e-12) & (series[:, 0] < start + width - 1e-12)
        if inside.any():
            r = series[inside, 1]
            print(f"  t = {start:.2f} s: mean {r.mean():.2f} [{r.min():.2f} .. {r.max():.2f}], {inside.sum()} frames")


def plot(out, panels):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(panels), figsize=(3.2 * len(panels), 3.6), constrained_layout=True)
    axes = np.atleast_1d(axes)
    for ax, panel in zip(axes, panels):
        run, frame, label = panel.split(":", 2)
        with h5py.File(os.path.join(run, "frames", f"frame_{int(frame):05d}.h5"), "r") as f:
            x, p, fluid, t = f["position"][()], f["pressure"][()], f["kind"][()] == 0, float(f.attrs["time"])
        drawn = ax.scatter(x[fluid, 0], x[fluid, 1], c=p[fluid] / 1000, s=0.05, cmap="coolwarm", vmin=-8, vmax=8,
                           rasterized=True)
        ax.set_aspect("equal")
        ax.set_xlim(0, 0.45)
        ax.set_ylim(0, 0.5)
        ax.set_title(f"{label}\nt = {t:.2f} s", fontsize=8)
        ax.tick_params(labelsize=7)
    bar = fig.colorbar(drawn, ax=axes, shrink=0.8)
    bar.set_label("pressure (kPa)", fontsize=8)
    fig.savefig(out, dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+", help="run directories (or RUN:FRAME:LABEL with --plot)")
    parser.add_argument("--spacing", type=float, help="the run's particle spacing d (m)")
    parser.add_argument("--x", type=float, default=0.1, help="where along the floor (m)")
    parser.add_argument("--window", type=float, default=0.02, help="window of the means (s)")
    parser.add_argument("--plot", help="draw the frames RUN:FRAME:LABEL into this PNG instead")
    a = parser.parse_args()
    if a.plot:
        plot(a.plot, a.runs)
        return
    if not a.spacing:
        parser.error("--spacing is required")
    for run in a.runs:
        windows(run, a.spacing, a.x, a.window)


if __name__ == "__main__":
    main()
