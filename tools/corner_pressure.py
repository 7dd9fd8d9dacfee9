"""The pressure in the column's back corner of a 2D dam break, frame by frame, from a run's frames.

In every frame: the fluid particles left of `--column` (0.2 m: what is left of the 0.25 m column),
the top of that water (its highest particle), and each particle's pressure above rho g times its
depth under that top (the excess). Printed: how many particles lie within `--radius` of the
corner (x, y) = (0, 0) and their mean excess, then the largest excess and the lowest over the
column and where they are. The pressure mode that blows up ISPH's dam break at a/d = 200
(docs/isph.md, "The column's pressure bursts") reads as a corner excess far above the rest, while
the count falls as the corner empties; it flips sign every step, so frames sample it at random
(a pressure probe at the corner with `output.probe_interval = 1e-6` follows it step by step).
Frames whose column has a drop flying above it misread the top: read the lines before the
surge's run-up falls back (t < 0.5 s at a = 0.25 m).

    /usr/bin/python3 tools/corner_pressure.py RUN_DIR [--from 0.2] [--column 0.2] [--radius 0.02]
"""
import argparse
import os

import h5py
import numpy as np

RHO_G = 1000.0 * 9.81


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('run_dir')
    ap.add_argument('--from', dest='t_from', type=float, default=0.0, help='first time to print (s)')
    ap.add_argument('--column', type=float, default=0.2, help='the column is the fluid left of this x (m)')
    ap.add_argument('--radius', type=float, default=0.02, help='the corner is the fluid this close to (0, 0) (m)')
    args = ap.parse_args()
    frames = os.path.join(args.run_dir, 'frames')
    if not os.path.isdir(frames):
        raise SystemExit('corner_pressure: %s has no frames/ folder' % args.run_dir)
    print('%7s %6s %14s %12s %17s %12s %17s' % ('t', 'corner', 'corner excess', 'largest', 'at', 'lowest', 'at'))
    for name in sorted(n for n in os.listdir(frames) if n.endswith('.h5')):
        with h5py.File(os.path.join(frames, name), 'r') as f:
            t = float(f.attrs['time'])
            if t < args.t_from:
                continue
            fluid = f['kind'][:] == 0
            x = f['position'][:][fluid]
            p = f['pressure'][:][fluid]
        column = x[:, 0] < args.column
        if not column.any():
            continue
        x, p = x[column], p[column]
        excess = p - RHO_G * (x[:, 1].max() - x[:, 1])
        corner = np.hypot(x[:, 0], x[:, 1]) < args.radius
        hi, lo = int(np.argmax(excess)), int(np.argmin(excess))
        print('%7.3f %6d %14.0f %12.0f  (%6.3f, %6.3f) %12.0f  (%6.3f, %6.3f)' % (
            t, corner.sum(), excess[corner].mean() if corner.any() else float('nan'), excess[hi], x[hi, 0], x[hi, 1],
            excess[lo], x[lo, 0], x[lo, 1]))


if __name__ == '__main__':
    main()
