"""Poiseuille channel of scenes/poiseuille_isph_2d.toml at any resolution, and its error against
the start-up series of Morris, Fox & Zhu (1997, eq. 21), as tests/poiseuille_test.cpp computes it.

    /usr/bin/python3 tools/poiseuille.py scene CELLS > channel.toml   # l/d = CELLS
    /usr/bin/python3 tools/poiseuille.py error RUN_DIR                # one line per frame

The geometry moves with d: wall particles on y = 0 and y = l = 1 mm, fluid rows d, 2d, ...,
buffers ([[fixed_pressure]]) three spacings long beyond x = 0 and x = L = 2 mm. The error is the
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


def scene(cells):
    d = WIDTH / cells
    b = 3 * d
    return f"""[scene]
dimension = 2
name = "poiseuille_{cells}"
[domain]
min = [{-b - 5e-4:.9g}, -0.0005]
max = [{LENGTH + b + 5e-4:.9g}, 0.0015]
[particles]
spacing = {d:.9g}
[material]
density = 1000.0
viscosity = 1.0e-3
[physics]
gravity = [0.0, 0.0]
[method]
name = "isph"
description = "eulerian"
[time]
end = 0.5
[output]
interval = 0.05
[[fluid]]
min = [{-b:.9g}, {d / 2:.9g}]
max = [{LENGTH + b:.9g}, {WIDTH - d / 2:.9g}]
[[wall]]
min = [{-b:.9g}, {d / 2:.9g}]
max = [{LENGTH + b:.9g}, {WIDTH - d / 2:.9g}]
open_ends = [true, false]
open_top = false
[[fixed_pressure]]
min = [{-b:.9g}, 0.0]
max = [0.0, 0.001]
pressure = 1.0
gradient = [-500.0, 0.0]
[[fixed_pressure]]
min = [0.002, 0.0]
max = [{LENGTH + b:.9g}, 0.001]
pressure = 1.0
gradient = [-500.0, 0.0]
"""


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
    if len(sys.argv) == 3 and sys.argv[1] == "scene":
        print(scene(int(sys.argv[2])), end="")
    elif len(sys.argv) == 3 and sys.argv[1] == "error":
        errors(sys.argv[2])
    else:
        sys.exit(__doc__)
