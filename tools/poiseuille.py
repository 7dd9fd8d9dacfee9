"""Poiseuille channel of scenes/poiseuille_isph_2d.toml at any resolution, and its error against
the start-up series of Morris, Fox & Zhu (1997, eq. 21), as tests/poiseuille_test.cpp computes it.

    eval build/ryushi run scenes/poiseuille_isph_2d.toml --out o $(/usr/bin/python3 tools/poiseuille.py sets 50)
    /usr/bin/python3 tools/poiseuille.py error o                      # one line per frame

`sets CELLS` prints the --set arguments for l/d = CELLS: the geometry moves with d (wall
particles on y = 0 and y = l = 1 mm, fluid rows d, 2d, ..., buffers ([[fixed_pressure]]) three
spacings long beyond x = 0 and x = L = 2 mm), as tests/poiseuille_test.cpp sets it. The error is the
L2 difference of u across the column nearest x = L/2, relative to the series' centreline speed.
"""
import glob
import math
import sys

WIDTH, LENGTH, NU = 1e-3, 2e-3, 1e-6
FORCE = 1.0 / (1000 * LENGTH)  # dp / (rho L)


def morris(y, t):
    u = FORCE / (2 * NU) * y * (WIDTH - y)
    for n in range(200):
        k = 2 * n + 1
        u -= (4 * FORCE * WIDTH ** 2 / (NU * math.pi ** 3 * k ** 3) * math.sin(k * math.pi * y / WIDTH)
              * math.exp(-k * k * math.pi ** 2 * NU * t / WIDTH ** 2))
    return u


def overrides(cells):
    """The key=value overrides that put scenes/poiseuille_isph_2d.toml at l/d = cells."""
    d = WIDTH / cells
    b = 3 * d
    vec = lambda x, y: f"[{x:.9g}, {y:.9g}]"
    pairs = [("particles.spacing", f"{d:.9g}"),
             ("domain.min", vec(-b - 5e-4, -5e-4)), ("domain.max", vec(LENGTH + b + 5e-4, WIDTH + 5e-4)),
             ("fluid.0.min", vec(-b, d / 2)), ("fluid.0.max", vec(LENGTH + b, WIDTH - d / 2)),
             ("wall.0.min", vec(-b, d / 2)), ("wall.0.max", vec(LENGTH + b, WIDTH - d / 2)),
             ("fixed_pressure.0.min", vec(-b, 0)), ("fixed_pressure.1.max", vec(LENGTH + b, WIDTH))]
    return [f"{k}={v}" for k, v in pairs]


def sets(cells):
    """The --set arguments that put scenes/poiseuille_isph_2d.toml at l/d = cells."""
    return " ".join(f"--set '{kv}'" for kv in overrides(cells))


def errors(run):
    import h5py
    import numpy as np
    for path in sorted(glob.glob(run + "/frames/*.h5")):
        with h5py.File(path, "r") as h:
            t = float(h.attrs["time"])
            x, v, kind = h["position"][:], h["velocity"][:], h["kind"][:]
        if t <= 0:
            continue
        fluid = kind == 0
        column = x[fluid, 0][np.argmin(np.abs(x[fluid, 0] - LENGTH / 2))]
        sel = fluid & (np.abs(x[:, 0] - column) < 1e-12)
        exact = np.array([morris(y, t) for y in x[sel, 1]])
        l2 = math.sqrt(np.mean((v[sel, 0] - exact) ** 2)) / morris(WIDTH / 2, t)
        print(f"t={t:.3f} l2={100 * l2:.4f}%")


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "sets":
        print(sets(int(sys.argv[2])))
    elif len(sys.argv) == 3 and sys.argv[1] == "error":
        errors(sys.argv[2])
    else:
        sys.exit(__doc__)
