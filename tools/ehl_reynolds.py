#!/usr/bin/python3
"""Reference solution of a soft elasto-hydrodynamic line contact (issue 55, acceptance 4): the
steady Reynolds equation with the film-thickness equation and the load balance of the soft-EHL
paper ("MPH法を用いたソフトEHLシミュレーション", eqs. 1-2), solved by finite differences, for the
MPH-I runs to be compared against.

  d/dx (h^3 dp/dx) = 6 mu U dh/dx          (U = u_plate + u_cylinder, isoviscous, incompressible)
  h(x) = h0 + x^2 / (2 R) + v(x),  v(x) = -(2 / (pi E)) int p(s) ln|x - s| ds     (eq. 1)

E is eq. 1's modulus as the paper writes it (1.95e7 Pa): with the coefficient 2 / (pi E) it is the
contact modulus E* of Hertz's line contact (1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2; the half-width
b = sqrt(4 W R / (pi E*))), i.e. half of the E' = 2 E* of the 4 / (pi E') convention.
  int p dx = W                                                                    (eq. 2)

Boundary conditions: p = 0 at the inlet (fully flooded) and the Reynolds (Swift-Stieber) outlet
condition, p >= 0 with p = dp/dx = 0 where the film cavitates, by an active set on the discrete
complementarity problem. The elastic deformation takes p piecewise constant on each cell (the
exact integral of ln|x - s| over the cell), so v's additive constant sits in h0, which the load
balance sets. The coupled problem is solved by under-relaxed fixed-point iteration on p and h0.

Prints the central film h(0), the minimum film and where, the load balance and two regime
estimates of the minimum film (Johnson, Contact Mechanics, 1985, section 13.5, with u_e = U/2 the
entraining speed and g_H = h_min W / (eta u_e R)): rigid-isoviscous (Martin) g_H = 4.9, and
isoviscous-elastic (Herrebrugh 1968) g_H = 3.01 g_E^0.8 with g_E = (W^2 / (eta u_e E* R))^(1/2);
--csv writes x, p, h.

    /usr/bin/python3 tools/ehl_reynolds.py [--cells 800] [--csv FILE]   (the paper's case)
"""
import argparse
import math

import numpy as np
from scipy.linalg import solve_banded


def deformation_matrix(x, dx, modulus):
    """K with v = K p: -(2 / (pi E)) times the integral of ln|x_i - s| over cell j."""
    def primitive(t):  # the integral of ln|t|: t ln|t| - t (0 at t = 0)
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(t == 0, 0.0, t * np.log(np.abs(t)) - t)
    xi = x[:, None]
    upper = x[None, :] + dx / 2 - xi
    lower = x[None, :] - dx / 2 - xi
    return -(2.0 / (math.pi * modulus)) * (primitive(upper) - primitive(lower))


def solve_reynolds(x, dx, h, mu, U, p_inlet=0.0):
    """p with p = 0 at the inlet node and from the outlet node k on, the largest k for which p >= 0
    everywhere: the film cavitates where the pressure would fall below zero, and there
    p = dp/dx = 0 to the grid's resolution (Swift-Stieber). One cavitated region, downstream."""
    n = len(x)
    h_face = (0.5 * (h[1:] + h[:-1])) ** 3  # h^3 on the faces between nodes
    source = np.zeros(n)
    source[1:-1] = 6 * mu * U * (h[2:] - h[:-2]) / 2 * dx

    def with_outlet(k):  # p_0 = p_inlet, p_k = 0, the nodes 1 .. k-1 solved, zero beyond
        p = np.zeros(n)
        p[0] = p_inlet
        inner = np.arange(1, k)
        if len(inner) == 0:
            return p
        rhs = source[inner].copy()
        rhs[0] -= h_face[0] * p_inlet
        bands = np.zeros((3, len(inner)))  # solve_banded's layout: upper, diagonal, lower
        bands[1] = -(h_face[inner - 1] + h_face[inner])
        bands[0, 1:] = h_face[inner[:-1]]
        bands[2, :-1] = h_face[inner[:-1]]
        p[inner] = solve_banded((1, 1), bands, rhs)
        return p

    lo, hi = 2, n - 1  # the largest k in [lo, hi] whose p has no negative value
    if (with_outlet(hi) >= 0).all():
        return with_outlet(hi)
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if (with_outlet(mid) >= -1e-12 * np.abs(with_outlet(mid)).max()).all():
            lo = mid
        else:
            hi = mid
    return with_outlet(lo)


def solve(R, modulus, W, U, mu, h_guess, cells, x_in, x_out, relax=0.1, iterations=20000, tol=1e-9, p_inlet=0.0):
    # The length unit: the Hertz half-width, or for a stiff body the rigid film's own width.
    b_hertz = max(math.sqrt(4 * W * R / (math.pi * modulus)), math.sqrt(2 * R * h_guess))
    x = np.linspace(x_in * b_hertz, x_out * b_hertz, cells + 1)
    dx = x[1] - x[0]
    K = deformation_matrix(x, dx, modulus)
    p = np.zeros_like(x)
    h0 = h_guess
    for it in range(iterations):
        h = h0 + x * x / (2 * R) + K @ p
        if h.min() <= 0:
            raise RuntimeError(f"the film closed (h0 = {h0:.3e}); lower relax")
        p_new = solve_reynolds(x, dx, h, mu, U, p_inlet)
        load = np.sum(p_new) * dx
        change = np.abs(p_new - p).max() / max(np.abs(p_new).max(), 1e-30)
        p = p + relax * (p_new - p)
        # The load balance moves the rigid approach (h0 holds v's additive constant, so it may be
        # negative): more load than W, the film opens, by a step of the current minimum film.
        h0 += relax * (load / W - 1) * h.min()
        if change < tol and abs(load / W - 1) < tol:
            break
    h = h0 + x * x / (2 * R) + K @ p
    return x, p, h, np.sum(p) * dx, it + 1, b_hertz


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--radius", type=float, default=0.1, help="R (m)")
    ap.add_argument("--modulus", type=float, default=1.95e7, help="E (Pa) of eq. 1, the contact modulus E*")
    ap.add_argument("--load", type=float, default=1.0e3, help="W (N per metre)")
    ap.add_argument("--speed", type=float, default=0.4, help="U, the sum of the surfaces' speeds (m/s)")
    ap.add_argument("--viscosity", type=float, default=8.31e-2, help="mu (Pa s)")
    ap.add_argument("--cells", type=int, default=800)
    ap.add_argument("--inlet", type=float, default=-4.0,
                    help="inlet, in Hertz half-widths b (or sqrt(2 R h) where that is wider)")
    ap.add_argument("--outlet", type=float, default=2.0, help="outlet, in the same unit")
    ap.add_argument("--relax", type=float, default=0.1)
    ap.add_argument("--csv", help="write x, p, h here")
    ap.add_argument("--table", help="write inlet (b), central film, minimum film, its place (b), peak pressure, "
                                    "one row per inlet of --inlets, here (the MPH-I test's reference)")
    ap.add_argument("--inlets", default="-1.5,-1.6,-1.7,-1.8,-1.9,-2.0,-2.2,-2.4,-2.6,-2.8,-3.0,-3.5,-4.0",
                    help="inlets (in b) for --table")
    ap.add_argument("--check", action="store_true",
                    help="solve a rigid cylinder (E = 1e13 Pa, 3200 cells from -64 to 3 film widths) and compare with "
                         "Martin's h_min = 4.895 eta u_e R / W (the constant from the Reynolds-condition integral); "
                         "exit 1 if 0.5% off")
    a = ap.parse_args()
    if a.check:
        x, p, h, load, its, b = solve(a.radius, 1e13, a.load, a.speed, a.viscosity,
                                      4.895 * a.viscosity * a.speed / 2 * a.radius / a.load, 3200, -64, 3, 0.3)
        martin = 4.895 * a.viscosity * a.speed / 2 * a.radius / a.load
        error = h.min() / martin - 1
        print(f"rigid cylinder: minimum film {h.min() * 1e6:.4f} um against Martin's {martin * 1e6:.4f} um ({error:+.2%})")
        raise SystemExit(0 if abs(error) < 0.005 else 1)
    if a.table:
        u_e = a.speed / 2
        johnson = 3.01 * math.sqrt(a.load ** 2 / (a.viscosity * u_e * a.modulus * a.radius)) ** 0.8 * a.viscosity * u_e * a.radius / a.load
        rows = []
        for inlet in [float(t) for t in a.inlets.split(",")]:
            x, p, h, load, its, b = solve(a.radius, a.modulus, a.load, a.speed, a.viscosity, johnson, a.cells,
                                          inlet, a.outlet, a.relax)
            k = int(np.argmin(h))
            rows.append([inlet, np.interp(0.0, x, h), h[k], x[k] / b, p.max()])
            print(f"inlet {inlet:+.2f} b: central {rows[-1][1] * 1e6:.2f} um, minimum {h[k] * 1e6:.2f} um")
        np.savetxt(a.table, np.array(rows), delimiter=",", fmt="%.8g",
                   header="inlet_b,central_film_m,minimum_film_m,minimum_at_b,peak_pressure_pa", comments="")
        return
    u_e = a.speed / 2
    g_e = math.sqrt(a.load ** 2 / (a.viscosity * u_e * a.modulus * a.radius))
    johnson = 3.01 * g_e ** 0.8 * a.viscosity * u_e * a.radius / a.load
    martin = 4.9 * a.viscosity * u_e * a.radius / a.load
    x, p, h, load, its, b = solve(a.radius, a.modulus, a.load, a.speed, a.viscosity, max(johnson, martin), a.cells,
                                  a.inlet, a.outlet, a.relax)
    centre = np.interp(0.0, x, h)
    k = int(np.argmin(h))
    b_hertz = math.sqrt(4 * a.load * a.radius / (math.pi * a.modulus))
    print(f"Hertz half-width {b_hertz * 1e3:.4f} mm, p_Hertz = {2 * a.load / (math.pi * b_hertz):.4e} Pa, "
          f"g_E = {g_e:.3f}, length unit b = {b * 1e3:.4f} mm")
    print(f"iterations {its}, load {load:.6e} N/m (W {a.load:.6e}, {load / a.load - 1:+.2e})")
    print(f"central film h(0) = {centre * 1e6:.3f} um, minimum film {h[k] * 1e6:.3f} um at x = {x[k] / b:.3f} b, "
          f"peak pressure {p.max():.4e} Pa at x = {x[np.argmax(p)] / b:.3f} b")
    print(f"isoviscous-elastic h_min = 3.01 g_E^0.8 eta u_e R / W = {johnson * 1e6:.3f} um (the solution's "
          f"{h[k] / johnson - 1:+.1%}); rigid-isoviscous 4.9 eta u_e R / W = {martin * 1e6:.3f} um")
    if a.csv:
        np.savetxt(a.csv, np.column_stack([x, p, h]), delimiter=",", header="x,p,h", comments="")


if __name__ == "__main__":
    main()
