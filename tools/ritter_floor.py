#!/usr/bin/env python3
"""The least front-region error eq. 7 allows on Ritter's dam break, whatever the dynamics.

Ritter's dry-bed dam break (seed 000, Saigo & Koshizuka section 3(1); docs/swe.md) has an exact
Lagrangian solution: a water element that starts at X < x_dam stays at rest until the
rarefaction reaches it at t1 = (x_dam - X) / c0 and then moves along
    x - x_dam = 2 c0 t - 3 c0 t1^(1/3) t^(2/3)          (dx/dt = u = 2/3 ((x - x_dam)/t + c0)).
This tool puts particles exactly there at time t, each with the volume its lattice cell held
(h0 d^2), mirrors them across the channel's walls as ryushi's ghosts do, computes every depth
with the method's own operator (eq. 7, the spiky kernel of eq. 8, one r_e = alpha_e sqrt(A_max)
of eq. 9, A = V / h, iterated until the areas and r_e agree) and measures the front-region error
exactly as summary.json does (src/systems/swe/ritter.hpp): sum |h_i - h(x_i)| / sum h(x_i) over
the particles at x >= x_dam.

Two samplings of the exact solution:
  unsplit  one particle per lattice cell (what a run without splitting can at best hold);
  split    each cell cut along x into the fewest equal slabs whose stretched area stays within
           area_ratio A0 (the ideal outcome of splitting at that threshold: every child where
           the exact solution puts its volume).
The simulation's error cannot be expected below these: they are the representation error of
eq. 7 at that spacing, with no time-stepping or splitting error at all.

    /usr/bin/python3 tools/ritter_floor.py [--spacing 0.1 0.05] [--time 0.5] [--area-ratio 1.5]
"""
import argparse

import numpy as np
from scipy.spatial import cKDTree

G, H0, X_DAM, X_BACK, WIDTH = 9.81, 0.25, 4.65, 0.05, 1.0  # the scene's column (dam_break_ritter_swe.toml)


def ritter_depth(x, t):
    c0 = np.sqrt(G * H0)
    xi = x - X_DAM
    s = 2 * c0 - xi / t
    return np.where(xi <= -c0 * t, H0, np.where(xi >= 2 * c0 * t, 0.0, s * s / (9 * G)))


def lagrangian_x(X, t):
    """Position at t of the water element that started at X (upstream of the dam)."""
    c0 = np.sqrt(G * H0)
    t1 = (X_DAM - X) / c0
    moved = X_DAM + 2 * c0 * t - 3 * c0 * np.cbrt(t1) * t ** (2.0 / 3.0)
    return np.where(t > t1, moved, X)


def spiky(r, re):
    q = r / re
    return np.where(q < 2, 5.0 / (16 * np.pi * re * re) * (2 - q) ** 3, 0.0)


def sample(d, t, area_ratio, split):
    """Particle positions and volumes of the exact solution at t."""
    xs, vs = [], []
    for X in np.arange(X_BACK + d / 2, X_DAM, d):
        k = 1
        if split:  # the cell's stretch along x; pieces of at most area_ratio A0
            stretch = (lagrangian_x(X + d / 2, t) - lagrangian_x(X - d / 2, t)) / d
            k = max(1, int(np.ceil(stretch / area_ratio - 1e-12)))
        for m in range(k):
            xs.append(lagrangian_x(X - d / 2 + (m + 0.5) * d / k, t))
            vs.append(H0 * d * d / k)
    rows = (np.arange(int(round(WIDTH / d))) + 0.5) * d
    P = np.array([(x, y) for y in rows for x in xs])
    V = np.tile(np.array(vs), len(rows))
    return P, V


def depths(P, V):
    """Eq. 7 with eq. 9's common radius, the channel's sides and back wall mirrored (ghosts)."""
    mirrors = [P, P * [1, -1], P * [1, -1] + [0, 2 * WIDTH]]
    allP = np.vstack(mirrors)
    allP = np.vstack([allP, allP * [-1, 1] + [2 * X_BACK, 0]])
    allV = np.tile(V, 6)
    tree = cKDTree(allP)
    A = V / H0
    for _ in range(100):
        re = 1.3 * np.sqrt(A.max())
        h = np.zeros(len(P))
        for i, nbrs in enumerate(tree.query_ball_point(P, 2 * re)):
            r = np.linalg.norm(allP[nbrs] - P[i], axis=1)
            h[i] = (allV[nbrs] * spiky(r, re)).sum()
        A_new = V / h
        if np.allclose(A_new, A, rtol=1e-12, atol=0):
            break
        A = A_new
    return h, re


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--spacing", type=float, nargs="+", default=[0.1, 0.05, 0.025])
    ap.add_argument("--time", type=float, default=0.5)
    ap.add_argument("--area-ratio", type=float, default=1.5)
    a = ap.parse_args()
    print("| d (m) | sampling | particles | r_e (m) | front-region error | wave error | foremost particle (m) |")
    print("|---|---|---|---|---|---|---|")
    for d in a.spacing:
        for split in (False, True):
            P, V = sample(d, a.time, a.area_ratio, split)
            h, re = depths(P, V)
            ref = ritter_depth(P[:, 0], a.time)
            front = P[:, 0] >= X_DAM
            fe = np.abs(h[front] - ref[front]).sum() / ref[front].sum()
            we = np.abs(h - ref).sum() / ref.sum()
            name = f"split at {a.area_ratio:g} A0" if split else "unsplit"
            print(f"| {d:g} | {name} | {len(P)} | {re:.4f} | {fe:.3f} | {we:.3f} | {P[:, 0].max():.3f} |")


if __name__ == "__main__":
    main()
