"""Poiseuille channel of scenes/poiseuille_isph_2d.toml (and pipe of poiseuille_isph_3d.toml) at any
resolution, and its error against the start-up series of Morris, Fox & Zhu (1997, eq. 21) (the pipe:
Szymanski's Bessel series), as tests/poiseuille_test.cpp computes it.

    eval build/ryushi run scenes/poiseuille_isph_2d.toml --out o $(/usr/bin/python3 tools/poiseuille.py sets 50)
    eval build/ryushi run scenes/poiseuille_isph_3d.toml --out o $(/usr/bin/python3 tools/poiseuille.py pipe-sets 20)
    /usr/bin/python3 tools/poiseuille.py error o                      # one line per frame
    /usr/bin/python3 tools/poiseuille.py plot o profile.png           # the profiles against the series

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


def szymanski(r, t):
    """Start-up flow in a pipe of radius WIDTH/2 from rest (lambda_n: the zeros of J0)."""
    from scipy.special import j0, j1, jn_zeros
    R = WIDTH / 2
    u = FORCE / (4 * NU) * (R * R - r * r)
    for lam in jn_zeros(0, 200):
        u = u - 2 * FORCE * R * R / NU * j0(lam * r / R) / (lam ** 3 * j1(lam)) * math.exp(-lam * lam * NU * t / R / R)
    return u


def pipe_overrides(cells):
    """The overrides that put scenes/poiseuille_isph_3d.toml at l/d = cells."""
    d, R = WIDTH / cells, WIDTH / 2
    b = 3 * d
    vec = lambda x, y, z: f"[{x:.9g}, {y:.9g}, {z:.9g}]"
    pairs = [("particles.spacing", f"{d:.9g}"), ("solid.0.radius", f"{R - d / 2:.9g}"),
             ("domain.min", vec(-b, -2 * R, -2 * R)), ("domain.max", vec(LENGTH + b, 2 * R, 2 * R)),
             ("fluid.0.min", vec(-b, -R, -R)), ("fluid.0.max", vec(LENGTH + b, R, R)),
             ("fixed_pressure.0.min", vec(-b, -2 * R, -2 * R)), ("fixed_pressure.1.max", vec(LENGTH + b, 2 * R, 2 * R))]
    return [f"{k}={v}" for k, v in pairs]


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


def sets(pairs):
    """The --set arguments for a list of overrides."""
    return " ".join(f"--set '{kv}'" for kv in pairs)


def profiles(run):
    """Per frame (t > 0): time, the cross coordinate (y, or r for a pipe), u, and the series there."""
    import h5py
    import numpy as np
    for path in sorted(glob.glob(run + "/frames/*.h5")):
        with h5py.File(path, "r") as h:
            t = float(h.attrs["time"])
            x, v, kind = h["position"][:], h["velocity"][:], h["kind"][:]
        if t <= 0:
            continue
        fluid = kind == 0
        pipe = np.abs(x[:, 2]).max() > 0
        column = x[fluid, 0][np.argmin(np.abs(x[fluid, 0] - LENGTH / 2))]
        sel = fluid & (np.abs(x[:, 0] - column) < 1e-12)
        across = np.hypot(x[sel, 1], x[sel, 2]) if pipe else x[sel, 1]
        exact = np.array([szymanski(c, t) if pipe else morris(c, t) for c in across])
        centre = szymanski(0.0, t) if pipe else morris(WIDTH / 2, t)
        yield t, pipe, across, v[sel, 0], exact, centre


def errors(run):
    import numpy as np
    for t, _, _, u, exact, centre in profiles(run):
        l2 = math.sqrt(np.mean((u - exact) ** 2)) / centre
        print(f"t={t:.3f} l2={100 * l2:.4f}%")


def plot(run, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    fig, ax = plt.subplots(figsize=(6, 4))
    pipe = False
    for t, pipe, across, u, _, _ in profiles(run):
        if round(t, 6) not in (0.05, 0.1, 0.2, 0.5):  # the start-up and the steady flow
            continue
        grid = np.linspace(0, WIDTH / 2 if pipe else WIDTH, 101)
        line, = ax.plot(grid * 1e3, [szymanski(c, t) if pipe else morris(c, t) for c in grid], lw=1)
        ax.plot(across * 1e3, u, "o", ms=3, color=line.get_color(), label=f"t = {t:g} s")
    ax.set_xlabel("r (mm)" if pipe else "y (mm)")
    ax.set_ylabel("u (m/s)")
    ax.set_title(("pipe: ISPH (dots) against Szymanski's series (lines)" if pipe
                  else "channel: ISPH (dots) against Morris et al.'s series (lines)"), fontsize=9)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "sets":
        print(sets(overrides(int(sys.argv[2]))))
    elif len(sys.argv) == 3 and sys.argv[1] == "pipe-sets":
        print(sets(pipe_overrides(int(sys.argv[2]))))
    elif len(sys.argv) == 3 and sys.argv[1] == "error":
        errors(sys.argv[2])
    elif len(sys.argv) == 4 and sys.argv[1] == "plot":
        plot(sys.argv[2], sys.argv[3])
    else:
        sys.exit(__doc__)
