"""Rotating square patch (scenes/rotating_square_isph_2d.toml): how long each shifting model keeps
the patch whole, as the ISPH paper's Figs. 3 and 5 compare them.

    for m in density optimised fickian none; do
      build/ryushi run scenes/rotating_square_isph_2d.toml --out rs_$m --set shifting.model=$m \\
        --set 'output.fields=["free_surface"]' --set output.interval=0.25 --quiet; done
    /usr/bin/python3 tools/rotating_square.py table rs_density rs_optimised rs_fickian rs_none
    /usr/bin/python3 tools/rotating_square.py plot out.png 2 rs_density rs_optimised rs_fickian rs_none

`table` prints, per frame: omega t, the number of interior particles, their numerical density
<rho>_i / rho0 (mean, lowest, highest) summed over the whole support 2 h (the fluid's volume:
compression shows here), and the same over the small radius d* = 1.1 sqrt(2) d of the ISPH
paper's eq. 19 (beta sum_{j in S*} m_j W_ij, beta making the lattice's value rho0: it also falls
when shear moves diagonal neighbours out past d*), then the number of
particles flagged as free surface. Interior: the particles that started in the inner square
|x|, |y| < 0.3 m (36% of the fluid, 0.2 m from the edge; followed by id) and have no flagged
particle within 2 h, so that eq. 19's sum is not cut by the surface. The arms thin to a few
particles as the patch stretches (the flow does that), so the count falls with time. `plot` draws each run's particles at
the given omega t coloured by <rho>_i / rho0 over 2 h, flagged surface particles outlined (the paper's
Fig. 5 at omega t = 2).
"""
import glob
import math
import os
import sys

SPACING, H_RATIO, OMEGA = 0.02, 1.2, 1.0


def cubic_spline(q):
    """Unnormalised cubic spline of q = r / h (the normalisation cancels in <rho> / rho0)."""
    w = 1 - 1.5 * q * q + 0.75 * q ** 3
    w = w if q < 1 else 0.25 * (2 - q) ** 3 if q < 2 else 0.0
    return w


S_STAR = 1.1 * math.sqrt(2) * SPACING  # eq. 19's small radius d* = 1.1 sqrt(D) d


def lattice_sum(h, radius):
    """The kernel summed over the starting lattice within radius (1 / beta of eq. 19 for d*)."""
    reach = int(math.ceil(radius / SPACING))
    return sum(cubic_spline(math.hypot(i, j) * SPACING / h) for i in range(-reach, reach + 1)
               for j in range(-reach, reach + 1) if math.hypot(i, j) * SPACING <= radius)


INNER = 0.3  # m, half the side of the interior square at the start


def inner_ids(run):
    import h5py
    import numpy as np
    with h5py.File(frames(run)[0], "r") as f:
        x0, ids = f["position"][:, :2], f["id"][:]
    return set(ids[np.max(np.abs(x0), axis=1) < INNER].tolist())


def frame_state(path, inner):
    """omega t, positions, the eq. 19 numerical density over rho0, interior mask, surface flags."""
    import h5py
    import numpy as np
    from scipy.spatial import cKDTree
    with h5py.File(path, "r") as f:
        t = float(f.attrs["time"])
        x = f["position"][:, :2]
        ids = f["id"][:]
        surface = f["free_surface"][:].astype(bool) if "free_surface" in f else np.zeros(len(x), bool)
    h = H_RATIO * SPACING
    tree = cKDTree(x)
    pairs = tree.query_pairs(2 * h, output_type="ndarray")  # i < j, no self pairs
    r = np.linalg.norm(x[pairs[:, 0]] - x[pairs[:, 1]], axis=1)
    w_all = np.vectorize(cubic_spline)(r / h)

    def summed(w, radius):
        return (np.bincount(pairs[:, 0], weights=w, minlength=len(x))
                + np.bincount(pairs[:, 1], weights=w, minlength=len(x)) + cubic_spline(0)) / lattice_sum(h, radius)
    density = summed(w_all, 2 * h), summed(np.where(r <= S_STAR, w_all, 0.0), S_STAR)
    started_inside = np.array([i in inner for i in ids.tolist()])
    # Full support: no flagged particle within 2 h (eq. 19's sum is not cut by the surface).
    near_surface = np.zeros(len(x), bool)
    for i, j in pairs:
        if surface[i] or surface[j]:
            near_surface[i] = near_surface[j] = True
    full_support = ~(surface | near_surface)
    return OMEGA * t, x, density, started_inside & full_support, surface


def frame_time(path):
    import h5py
    with h5py.File(path, "r") as f:
        return OMEGA * float(f.attrs["time"])


def frames(run):
    paths = sorted(glob.glob(os.path.join(run, "frames", "frame_*.h5")))
    if not paths:
        sys.exit(f"rotating_square.py: no frames in {run}/frames")
    return paths


def table(runs):
    for run in runs:
        print(f"# {run}")
        inner = inner_ids(run)
        print(f"{'omega t':>8} {'interior':>8} {'mean 2h':>8} {'min':>7} {'max':>7} {'mean d*':>8} {'min':>7} "
              f"{'max':>7} {'surface':>8}")
        for path in frames(run):
            wt, _, (full, small), interior, surface = frame_state(path, inner)
            n = int(interior.sum())
            cells = "".join(f" {d.mean():8.4f} {d.min():7.4f} {d.max():7.4f}" if n else f" {'-':>8} {'-':>7} {'-':>7}"
                            for d in (full[interior], small[interior]))
            print(f"{wt:8.2f} {n:8d}{cells} {int(surface.sum()):8d}")


def plot(png, omega_t, runs):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(runs), figsize=(3.3 * len(runs) + 1, 3.6), squeeze=False, layout="constrained")
    for ax, run in zip(axes[0], runs):
        inner = inner_ids(run)
        path = min(frames(run), key=lambda p: abs(frame_time(p) - omega_t))
        wt, x, (density, _), interior, surface = frame_state(path, inner)
        sc = ax.scatter(x[:, 0], x[:, 1], c=density, s=2, cmap="coolwarm", vmin=0.9, vmax=1.1)
        ax.scatter(x[surface, 0], x[surface, 1], s=6, facecolors="none", edgecolors="k", linewidths=0.3)
        d = density[interior]
        mean = f"{d.mean():.3f}" if len(d) else "-"
        ax.set_title(f"{os.path.basename(run.rstrip('/'))}: omega t = {wt:.2f}\n"
                     f"interior <rho>/rho0 {mean}, {int(surface.sum())} flagged", fontsize=8)
        ax.set_aspect("equal")
        ax.set_xlim(-1.6, 1.6)
        ax.set_ylim(-1.6, 1.6)
        ax.tick_params(labelsize=6)
    fig.colorbar(sc, ax=axes[0].tolist(), shrink=0.8, label="<rho>_i / rho0 (sum over 2 h)")
    fig.savefig(png, dpi=130)
    print(f"wrote {png}")


def main(argv):
    if len(argv) >= 2 and argv[0] == "table":
        table(argv[1:])
    elif len(argv) >= 4 and argv[0] == "plot":
        plot(argv[1], float(argv[2]), argv[3:])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv[1:])
