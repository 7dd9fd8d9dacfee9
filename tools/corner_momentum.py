#!/usr/bin/env python3
"""The back corner's pressure of a 2D dam break against the vertical momentum balance along the
back wall (docs/isph.md, "The back corner's pressure").

Along the wall x = 0 the water's vertical momentum reads dp/dz = -rho (g + a_z), a_z the vertical
acceleration of the fluid there, so with p = 0 at the top (height h):

    p(0) = rho g h + rho * integral_0^h a_z dz.

Once the column by the wall slows its fall (a_z > 0 near the floor) the corner reads more than rho g h:
an excess over the local hydrostatic pressure is not by itself an error. Between two consecutive frames
the tool takes the particles within a spacing of the wall (one per spacing up the column), a_z from
their velocities by id, the integral as sum a_z d, and h as the highest of them plus d/2; the measured
corner excess is the mean of p - rho g (h - z) over the particles within 3 spacings of (0, 0).
Printed per frame pair: the measured excess, the balance's, their difference in % of rho g H (H = the
column's first height). Frames every few ms: the accelerations are differences of the velocity.

    /usr/bin/python3 tools/corner_momentum.py RUN_DIR --spacing 0.00625 [--height 0.5] [--every 3]
"""
import argparse
import glob
import os

import h5py
import numpy as np

RHO, G = 1000.0, 9.81


def load(path):
    with h5py.File(path) as f:
        fluid = f['kind'][:] == 0
        return (float(f.attrs['time']), f['id'][:][fluid], f['position'][:][fluid], f['velocity'][:][fluid],
                f['pressure'][:][fluid])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('run_dir')
    ap.add_argument('--spacing', type=float, required=True, help='the particle spacing d (m)')
    ap.add_argument('--height', type=float, default=0.5, help="the column's first height H (m)")
    ap.add_argument('--every', type=int, default=1, help='print every n-th frame pair')
    a = ap.parse_args()
    d = a.spacing
    frames = sorted(glob.glob(os.path.join(a.run_dir, 'frames', 'frame_*.h5')))
    print('      t        h   corner excess   momentum balance   difference (% of rho g H)')
    previous = load(frames[0])
    for n, path in enumerate(frames[1:]):
        current = load(path)
        (t0, id0, x0, v0, p0), (t1, id1, x1, v1, p1) = previous, current
        previous = current
        common = np.intersect1d(id0, id1)
        o0, o1 = np.argsort(id0), np.argsort(id1)
        k0 = o0[np.searchsorted(id0[o0], common)]
        k1 = o1[np.searchsorted(id1[o1], common)]
        x = 0.5 * (x0[k0] + x1[k1])
        a_z = (v1[k1][:, 1] - v0[k0][:, 1]) / (t1 - t0)
        p = 0.5 * (p0[k0] + p1[k1])
        wall = x[:, 0] < d  # the first column (at d/2); the second stands at 1.5 d
        corner = np.hypot(x[:, 0], x[:, 1]) < 3 * d
        if wall.sum() < 3 or not corner.any() or n % a.every:
            continue
        h = x[wall, 1].max() + 0.5 * d
        balance = RHO * a_z[wall].sum() * d
        measured = np.mean(p[corner] - RHO * G * (h - x[corner, 1]))
        print('%7.3f %8.3f %15.0f %18.0f %12.1f' % (0.5 * (t0 + t1), h, measured, balance,
                                                     100 * (measured - balance) / (RHO * G * a.height)))


if __name__ == '__main__':
    main()
