#!/usr/bin/env python3
"""Which kernel and smoothing ratio hold a particle lattice under pressure (docs/isph.md, "Which
kernel holds a lattice under pressure").

SPH's symmetric pressure force, a_i = -sum_j m_j (p_i/rho_i^2 + p_j/rho_j^2) grad W_ij, under a
uniform pressure p is a_i = -(2 p V / rho) sum_j grad W(x_i - x_j) on a lattice of volume V per
particle. Displace the particles by a mode u_j = u exp(i k . x_j): to first order

    u'' = -(2 p V / rho) K(k) u,    K(k) = sum_j H(r_j) (1 - cos k . r_j),  H = grad grad W,

and each particle's kernel sum changes by i s(k) . u, s(k) = sum_j grad W(r_j) sin(k . r_j). An
incompressible solve (ISPH's implicit density formulation, DFSPH, IISPH) answers only that change:
its pressure acts along s(k) and removes that direction. Across it nothing answers but K, so a
negative eigenvalue of K projected off s(k) is a mode that grows at

    rate = sqrt(2 (p / rho) V |lambda|)           (lambda in units of the spacing d = 1).

At the checkerboards (k on the edge of the Brillouin zone) s(k) = 0 and all of K counts. The scan
below reports, per kernel and smoothing ratio h/d, the lowest eigenvalue over the wave vectors at
least pi/(2d) long (the particle-scale modes; near k = 0 K vanishes as k^2), and the rate it gives
at a depth where p / rho = `--head` m^2/s^2 and a spacing `--spacing` m.

Usage: /usr/bin/python3 tools/kernel_stability.py [--kernel wendland_c2] [--dimension 3]
           [--ratios 0.9:1.5:0.05] [--head 2.0] [--spacing 0.02] [--samples 12]
"""
import argparse
import itertools

import numpy as np

# f(q), q = r/h: first and second derivatives, support (in h), normalisation (2D, 3D) as in
# src/kernels/kernel.hpp.
KERNELS = {
    "cubic_spline": (
        lambda q: np.where(q < 1, -3 * q + 2.25 * q * q, np.where(q < 2, -0.75 * (2 - q) ** 2, 0.0)),
        lambda q: np.where(q < 1, -3 + 4.5 * q, np.where(q < 2, 1.5 * (2 - q), 0.0)),
        2.0, {2: 10 / (7 * np.pi), 3: 1 / np.pi}),
    "wendland_c2": (
        lambda q: np.where(q < 2, -5 * q * (1 - q / 2) ** 3, 0.0),
        lambda q: np.where(q < 2, -5 * (1 - q / 2) ** 3 + 7.5 * q * (1 - q / 2) ** 2, 0.0),
        2.0, {2: 7 / (4 * np.pi), 3: 21 / (16 * np.pi)}),
    "quintic_spline": (
        lambda q: -5 * sum(c * np.where(q < a, (a - q) ** 4, 0.0) for a, c in ((3, 1), (2, -6), (1, 15))),
        lambda q: 20 * sum(c * np.where(q < a, (a - q) ** 3, 0.0) for a, c in ((3, 1), (2, -6), (1, 15))),
        3.0, {2: 7 / (478 * np.pi), 3: 3 / (359 * np.pi)}),
}


def lowest_eigenvalue(kernel, dimension, ratio, samples):
    """The lowest eigenvalue of K projected off s(k), over the lattice's particle-scale modes."""
    d1, d2, support, sigma = KERNELS[kernel]
    reach = support * ratio
    m = int(np.ceil(reach)) + 1
    r_vec = np.array([p for p in itertools.product(range(-m, m + 1), repeat=dimension)
                      if 0 < np.linalg.norm(p) < reach], dtype=float)
    r = np.linalg.norm(r_vec, axis=1)
    e = r_vec / r[:, None]
    scale = sigma[dimension] / ratio ** dimension
    w1 = scale * d1(r / ratio) / ratio  # dW/dr
    w2 = scale * d2(r / ratio) / ratio ** 2  # d2W/dr2
    eye = np.eye(dimension)
    outer = e[:, :, None] * e[:, None, :]
    hessian = w2[:, None, None] * outer + (w1 / r)[:, None, None] * (eye[None] - outer)
    grad = w1[:, None] * e
    lowest, at = np.inf, None
    for k in itertools.product(np.linspace(0, np.pi, samples + 1), repeat=dimension):
        k = np.array(k)
        if np.linalg.norm(k) < 0.5 * np.pi:
            continue
        phase = r_vec @ k
        K = np.einsum("n,nab->ab", 1 - np.cos(phase), hessian)
        s = np.einsum("n,na->a", np.sin(phase), grad)
        if np.linalg.norm(s) > 1e-9 * np.abs(grad).sum():
            # K on the complement of s(k): an orthonormal basis of it from the SVD of s^T.
            basis = np.linalg.svd(s[None, :])[2][1:].T
            values = np.linalg.eigvalsh(basis.T @ K @ basis)
        else:
            values = np.linalg.eigvalsh(K)
        if values.min() < lowest:
            lowest, at = values.min(), k / np.pi
    return lowest, at, len(r)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--kernel", default="wendland_c2,cubic_spline", help="comma-separated")
    ap.add_argument("--dimension", default="2,3", help="comma-separated")
    ap.add_argument("--ratios", default="0.9:1.5:0.05", help="first:last:step of h/d")
    ap.add_argument("--head", type=float, default=2.0, help="p/rho (m^2/s^2): 2 is 0.2 m of water")
    ap.add_argument("--spacing", type=float, default=0.02, help="d (m) for the growth rate")
    ap.add_argument("--samples", type=int, default=12, help="wave vectors per axis over [0, pi/d]")
    a = ap.parse_args()
    first, last, step = (float(x) for x in a.ratios.split(":"))
    print("kernel dimension h/d neighbours lowest_eigenvalue at_k/(pi/d) growth_rate_1/s")
    for kernel in a.kernel.split(","):
        for dimension in (int(x) for x in a.dimension.split(",")):
            for ratio in np.arange(first, last + 1e-9, step):
                lam, at, n = lowest_eigenvalue(kernel, dimension, ratio, a.samples)
                rate = np.sqrt(max(0.0, -2 * a.head * lam)) / a.spacing
                print(f"{kernel} {dimension} {ratio:.2f} {n} {lam:+.4f} {np.round(at, 2).tolist()} {rate:.1f}")


if __name__ == "__main__":
    main()
