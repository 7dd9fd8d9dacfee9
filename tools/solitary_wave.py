#!/usr/bin/env python3
"""A solitary-wave run's crest at its gauges, its energy after the paddle stops, and its particle noise
(docs/isph.md, "The solitary wave"; scenes/solitary_wave_isph_2d.toml).

- Crest: the largest reading of each `water_height` probe in probes.csv, less the still depth, against
  the wave height H.
- Energy per metre of flume from every frame: kinetic and potential (rho g z, against the first frame),
  each particle's mass rho0 d^2. After the paddle stops the sum is the wave's loss; a potential energy that
  keeps rising with no wave to lift it is the fluid swelling (its level rising).
- Noise: around the crest (within 1 m), the rms of each particle's velocity less the mean over its
  neighbours within 3 d, against the rms speed there. A wave that leaves the lattice disordered carries
  a particle-scale velocity no smooth flow has.

    /usr/bin/python3 tools/solitary_wave.py RUN_DIR [--depth 0.2] [--height 0.04] [--noise-frame 5]
"""
import argparse
import csv
import glob
import json
import os

import h5py
import numpy as np
from scipy.spatial import cKDTree

RHO, G = 1000.0, 9.81


def crests(run, depth, height):
    with open(os.path.join(run, "probes.csv")) as f:
        rows = list(csv.DictReader(f))
    names = [k for k in rows[0] if k.startswith("eta")]
    for name in names:
        eta = np.array([float(r[name]) for r in rows]) - depth
        i = int(np.argmax(eta))
        print("%-10s crest %.4f m, %+.1f%% of H, at t = %.3f s" % (name, eta[i], 100 * (eta[i] / height - 1),
                                                               float(rows[i]["time"])))


def frames(run):
    return sorted(glob.glob(os.path.join(run, "frames", "frame_*.h5")))


def fluid(path):
    with h5py.File(path) as f:
        keep = f["kind"][:] == 0
        return float(f.attrs["time"]), f["position"][:][keep][:, :2], f["velocity"][:][keep][:, :2]


def energies(run, d):
    mass = RHO * d * d
    first = None
    for path in frames(run):
        t, x, v = fluid(path)
        kinetic, potential = 0.5 * mass * (v ** 2).sum(), mass * G * x[:, 1].sum()
        first = potential if first is None else first
        print("t = %5.2f s  kinetic %7.3f J/m  potential %7.3f J/m  sum %7.3f J/m" %
              (t, kinetic, potential - first, kinetic + potential - first))


def noise(run, d, index):
    t, x, v = fluid(frames(run)[index])
    bins = np.arange(x[:, 0].min(), x[:, 0].max() + 2 * d, 2 * d)
    column = np.digitize(x[:, 0], bins)
    tops = np.array([x[column == c, 1].max() if (column == c).any() else -np.inf for c in range(1, len(bins))])
    crest = bins[int(np.argmax(tops))] + d
    near = np.abs(x[:, 0] - crest) < 1.0
    tree = cKDTree(x)
    mean = np.array([v[n].mean(axis=0) for n in tree.query_ball_point(x[near], 3 * d)])
    rms = np.sqrt(((v[near] - mean) ** 2).sum(axis=1).mean())
    speed = np.sqrt((v[near] ** 2).sum(axis=1).mean())
    print("t = %.2f s, crest at x = %.2f m: noise rms %.2e m/s, %.1f%% of the rms speed %.3f m/s" %
          (t, crest, rms, 100 * rms / speed, speed))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run")
    ap.add_argument("--depth", type=float, default=0.2)
    ap.add_argument("--height", type=float, default=0.04)
    ap.add_argument("--noise-frame", type=int, default=5)
    a = ap.parse_args()
    with open(os.path.join(a.run, "summary.json")) as f:
        d = json.load(f)["parameters"]["spacing"]
    crests(a.run, a.depth, a.height)
    energies(a.run, d)
    noise(a.run, d, a.noise_frame)


if __name__ == "__main__":
    main()
