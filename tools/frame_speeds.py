"""What sets a projection method's step, frame by frame: the fastest fluid particle of each frame
of a run directory (speed, place and pressure), the 99.9th percentile of the fluid's speeds, how
many particles move faster than --fast (m/s), and the mean step between this frame and the one
before (from the frames' `step` and `time` attributes). MPS and ISPH take dt = cfl d / max|v|
(src/systems/integrate/velocity_time_step.hpp), so one particle thrown fast shortens every step
after it: this shows when and where that happened (docs/benchmarks.md, "Time to t = 1 s").

    /usr/bin/python3 tools/frame_speeds.py RUN_DIR [--from 0.3] [--fast 6.26]
"""
import argparse
import os

import h5py
import numpy as np


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('run_dir')
    ap.add_argument('--from', dest='t_from', type=float, default=0.0, help='first time to print (s)')
    ap.add_argument('--fast', type=float, default=6.26,
                    help='count particles faster than this (m/s; default 2 sqrt(2 g H) for H = 0.5 m)')
    args = ap.parse_args()
    frames = os.path.join(args.run_dir, 'frames')
    if not os.path.isdir(frames):
        raise SystemExit('frame_speeds: %s has no frames/ folder' % args.run_dir)
    print('%8s %8s %9s %7s %7s %6s %17s %9s' % ('t', 'step', 'mean dt', 'vmax', 'v99.9', 'n>fast', 'fastest at', 'its p'))
    before = None
    for name in sorted(n for n in os.listdir(frames) if n.endswith('.h5')):
        with h5py.File(os.path.join(frames, name), 'r') as f:
            t, step = float(f.attrs['time']), int(f.attrs['step'])
            fluid = f['kind'][:] == 0
            speed = np.linalg.norm(f['velocity'][:][fluid], axis=1)
            x = f['position'][:][fluid]
            p = f['pressure'][:][fluid]
        dt = (t - before[0]) / (step - before[1]) if before and step > before[1] else float('nan')
        before = (t, step)
        if t < args.t_from or speed.size == 0:
            continue
        i = int(np.argmax(speed))
        print('%8.4f %8d %9.2e %7.2f %7.2f %6d  (%6.3f, %6.3f) %9.0f' % (
            t, step, dt, speed[i], np.percentile(speed, 99.9), int((speed > args.fast).sum()), x[i, 0], x[i, 1], p[i]))


if __name__ == '__main__':
    main()
