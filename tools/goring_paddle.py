#!/usr/bin/env python3
"""A piston paddle's motion that makes a solitary wave (Goring 1978), as a [[solid]]
displacement_table (t, dx, dy).

The wave is the first-order (Boussinesq) solitary wave on still water of depth h,

    eta(x, t) = H sech^2(kappa (c (t - t0) - x)),   kappa = sqrt(3 H / (4 h^3)),   c = sqrt(g (h + H)),

and the paddle moves with the water under the crest's depth-averaged velocity,

    dX/dt = c eta(X, t) / (h + eta(X, t)),

integrated here by fourth-order Runge-Kutta. t0 puts the crest where the wave's elevation at the
paddle at t = 0 is `--start` H (0.002: the paddle starts from rest); the stroke is then close to
sqrt(16 H h / 3) and the motion lasts until the elevation at the paddle is back at `--start` H,
a little over 2 t0.

    /usr/bin/python3 tools/goring_paddle.py --depth 0.2 --height 0.04 OUT.csv [--dt 0.001] [--start 0.002]
"""
import argparse
import math


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('out')
    ap.add_argument('--depth', type=float, required=True, help='still-water depth h (m)')
    ap.add_argument('--height', type=float, required=True, help='wave height H (m)')
    ap.add_argument('--g', type=float, default=9.81)
    ap.add_argument('--dt', type=float, default=0.001, help='the table\'s time step (s)')
    ap.add_argument('--start', type=float, default=0.002, help='eta at the paddle at t = 0, over H')
    a = ap.parse_args()
    h, H = a.depth, a.height
    if not (h > 0 and 0 < H < h):
        raise SystemExit('goring_paddle.py: need 0 < height < depth')
    kappa = math.sqrt(3 * H / (4 * h ** 3))
    c = math.sqrt(a.g * (h + H))
    t0 = math.acosh(1 / math.sqrt(a.start)) / (kappa * c)

    def speed(t, x):
        eta = H / math.cosh(kappa * (c * (t - t0) - x)) ** 2
        return c * eta / (h + eta)

    # Until the wave's elevation at the paddle is back at `start` H behind the crest.
    phase_end = math.acosh(1 / math.sqrt(a.start))
    t, x, rows = 0.0, 0.0, []
    while kappa * (c * (t - t0) - x) < phase_end or t <= t0:
        rows.append((t, x))
        k1 = speed(t, x)
        k2 = speed(t + a.dt / 2, x + a.dt / 2 * k1)
        k3 = speed(t + a.dt / 2, x + a.dt / 2 * k2)
        k4 = speed(t + a.dt, x + a.dt * k3)
        x += a.dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        t += a.dt
    with open(a.out, 'w') as f:
        f.write('t,dx,dy\n')
        for t, x in rows:
            f.write('%.6f,%.9f,0\n' % (t, x))
    print('goring_paddle.py: kappa %.4f 1/m, c %.4f m/s, t0 %.4f s, stroke %.4f m (sqrt(16 H h / 3) = %.4f), %d rows'
          % (kappa, c, t0, rows[-1][1], math.sqrt(16 * H * h / 3), len(rows)))


if __name__ == '__main__':
    main()
