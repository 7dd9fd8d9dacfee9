#!/usr/bin/python3
"""Compares an MPH-I soft-EHL run (scenes/ehl_soft_mph_2d.toml, elastic_line_contact) with the
Reynolds-equation solution of the same contact (tools/ehl_reynolds.py), issue 55 acceptance 4.

From a frame it reads the surface particles' film_position, film_pressure and film_thickness (one
value per surface column) and the fluid particles, and finds the inlet meniscus: the most upstream
column of the filled film that runs unbroken to the contact's centre (a column is filled where a
fluid particle lies within 1.5 spacings of the face). The reference is solved with its inlet there
(p = 0) and the Reynolds outlet condition, on the same R, E, W, U and mu; it prints both films
(central, minimum), the load int p dx against W, the pressure's peak, the pressure's L2 difference
relative to the reference's peak over the reference's extent, and the minimum film against
Herrebrugh's isoviscous-elastic formula; --plot draws both; --json writes the figures.

    /usr/bin/python3 tools/ehl_compare.py RUN_DIR [--frame N] [--history] [--plot FILE] [--json FILE]
"""
import argparse
import glob
import json
import math
import os
import sys
import tomllib

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ehl_reynolds import solve, solve_reynolds  # noqa: E402


def contact_keys(scene_text):
    """The elastic_line_contact entry's numbers, the scene's spacing and viscosity, and the plate's speed
    (the fastest [[solid]] velocity)."""
    scene = tomllib.loads(scene_text)
    entry = next(t for t in scene.get("systems", []) if t.get("name") == "elastic_line_contact")
    keys = {k: entry.get(k) for k in ("radius", "modulus", "load")}
    keys["centre"] = entry.get("centre", 0.5 * (scene["domain"]["min"][0] + scene["domain"]["max"][0]))
    keys["plate"] = entry.get("plate", 0.0)
    keys["spacing"] = scene["particles"]["spacing"]
    keys["viscosity"] = scene["material"]["viscosity"]
    keys["speed"] = max(math.hypot(*s.get("velocity", [0.0])) for s in scene.get("solid", [{}]))
    return keys


def read_frame(path):
    with h5py.File(path, "r") as f:
        kind = f["kind"][:]
        x = f["position"][:]
        if "contact_slot" not in f:
            raise SystemExit(f"{path}: no film_position: list contact_slot, film_position, film_pressure, "
                             "film_thickness in [output] fields")
        slot = f["contact_slot"][:]
        first = (slot > 0)
        cols = {}
        for i in np.nonzero(first)[0]:
            cols.setdefault(round(f["film_position"][i], 12), (f["film_pressure"][i], f["film_thickness"][i]))
        xc = np.array(sorted(cols))
        p = np.array([cols[k][0] for k in xc])
        h = np.array([cols[k][1] for k in xc])
        fluid = x[kind == 0]
    return xc, p, h, fluid


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run")
    ap.add_argument("--frame", type=int, default=-1, help="the frame's index (default: the last)")
    ap.add_argument("--scene", help="the scene file (default: the run's summary.json names it)")
    ap.add_argument("--history", action="store_true",
                    help="print the load, central and minimum film of every frame (how the film settles)")
    ap.add_argument("--plot")
    ap.add_argument("--json")
    a = ap.parse_args()
    frames = sorted(glob.glob(os.path.join(a.run, "frames", "frame_*.h5")))
    if not frames:
        raise SystemExit(f"{a.run}: no frames")
    frame = frames[a.frame]
    scene = a.scene or json.load(open(os.path.join(a.run, "summary.json")))["scene_file"]
    k = contact_keys(open(scene).read())
    l = k["spacing"]
    if a.history:
        for path in frames:
            hx, hp, hh, _ = read_frame(path)
            with h5py.File(path, "r") as f:
                t = f.attrs.get("time", float("nan"))
            print(f"{os.path.basename(path)} t = {float(np.ravel(t)[0]):.4g} s: load {np.sum(hp) * l:8.1f} N/m, "
                  f"central film {np.interp(k['centre'], hx, hh) * 1e6:8.1f} um, minimum {hh.min() * 1e6:8.1f} um")
    xc, p, h, fluid = read_frame(frame)
    face = k["plate"] + h
    # Filled columns: a fluid particle within 1.5 spacings of the face.
    top = np.full(len(xc), -np.inf)
    col = np.rint((fluid[:, 0] - xc[0]) / l).astype(int)
    ok = (col >= 0) & (col < len(xc))
    np.maximum.at(top, col[ok], fluid[ok, 1])
    filled = face - top < 2.0 * l
    centre = int(np.argmin(np.abs(xc - k["centre"])))
    start, gap = centre, 0
    for c in range(centre - 1, -1, -1):  # upstream, across breaks of up to 3 columns
        gap = 0 if filled[c] else gap + 1
        if gap > 3:
            break
        if filled[c]:
            start = c
    inlet = xc[start] - 0.5 * l
    p_inlet = float(np.mean(p[start:start + 3]))  # the film's pressure at the meniscus
    W, R, E, mu, U = k["load"], k["radius"], k["modulus"], k["viscosity"], k["speed"]
    b = math.sqrt(4 * W * R / (math.pi * E))
    u_e = U / 2
    johnson = 3.01 * math.sqrt(W * W / (mu * u_e * E * R)) ** 0.8 * mu * u_e * R / W
    rx, rp, rh, rload, its, unit = solve(R, E, W, U, mu, johnson, 400, (inlet - k["centre"]) / b, 2.0, 0.1,
                                         p_inlet=p_inlet)
    rx = rx + k["centre"]
    zx, zp, zh, _, _, _ = solve(R, E, W, U, mu, johnson, 400, (inlet - k["centre"]) / b, 2.0, 0.1)
    load = float(np.sum(p) * l)
    # The hydrodynamics alone: Reynolds' pressure on the run's own film (same inlet and pressure there).
    own = (xc >= inlet) & (xc <= rx[-1])
    own_p = solve_reynolds(xc[own], l, h[own], mu, U, p_inlet)
    own_load = float(np.sum(own_p) * l)
    hc = float(np.interp(k["centre"], xc, h))
    rhc = float(np.interp(k["centre"], rx, rh))
    window = (xc > inlet) & (xc < rx[-1])
    hmin = float(h[window].min())
    inside = (rx >= xc[0]) & (rx <= xc[-1])
    pm = np.interp(rx[inside], xc, p)
    l2 = float(np.sqrt(np.mean((pm - rp[inside]) ** 2)) / rp.max())
    out = {"frame": os.path.basename(frame), "inlet_b": (inlet - k["centre"]) / b, "inlet_pressure": p_inlet,
           "zero_inlet_central_film": float(np.interp(0.0, zx, zh)), "zero_inlet_minimum_film": float(zh.min()),
           "load": load, "load_error": load / W - 1,
           "central_film": hc, "reference_central_film": rhc, "central_error": hc / rhc - 1,
           "minimum_film": hmin, "reference_minimum_film": float(rh.min()), "minimum_error": hmin / rh.min() - 1,
           "minimum_at_b": float((xc[window][np.argmin(h[window])] - k["centre"]) / b),
           "reference_minimum_at_b": float((rx[np.argmin(rh)] - k["centre"]) / b),
           "peak_pressure": float(p.max()), "reference_peak_pressure": float(rp.max()),
           "pressure_l2": l2, "reynolds_load_on_own_film": own_load, "herrebrugh_minimum_film": johnson, "herrebrugh_error": hmin / johnson - 1}
    print(f"{out['frame']}: inlet meniscus at {out['inlet_b']:.3f} b (b = {b * 1e3:.3f} mm), the film's pressure "
          f"there {p_inlet:.4g} Pa (the reference's inlet value; with p = 0 there: central "
          f"{out['zero_inlet_central_film'] * 1e6:.1f} um, minimum {out['zero_inlet_minimum_film'] * 1e6:.1f} um)")
    print(f"load {load:.1f} N/m against W = {W:.1f} ({out['load_error']:+.2%})")
    print(f"central film {hc * 1e6:.1f} um, reference {rhc * 1e6:.1f} um ({out['central_error']:+.2%})")
    print(f"minimum film {hmin * 1e6:.1f} um at {out['minimum_at_b']:.3f} b, reference {rh.min() * 1e6:.1f} um at "
          f"{out['reference_minimum_at_b']:.3f} b ({out['minimum_error']:+.2%})")
    print(f"peak pressure {p.max():.4g} Pa, reference {rp.max():.4g} Pa; pressure L2 {l2:.2%} of the reference's peak")
    print(f"Reynolds' pressure on the run's own film carries {own_load:.1f} N/m ({load / own_load - 1:+.2%} "
          f"in the run), peaks at {own_p.max():.4g} Pa")
    print(f"Herrebrugh's isoviscous-elastic minimum film {johnson * 1e6:.1f} um: {out['herrebrugh_error']:+.1%}")
    if a.json:
        json.dump(out, open(a.json, "w"), indent=1)
    if a.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(7, 6))
        ax1.plot(xc / b, p / 1e3, ".", ms=3, label="MPH-I (column means)")
        ax1.plot((rx - k["centre"]) / b, rp / 1e3, "-", label="Reynolds (same inlet)")
        ax1.set_ylabel("p (kPa)")
        ax1.legend()
        ax2.plot(xc / b, h * 1e3, ".", ms=3, label="MPH-I surface")
        ax2.plot((rx - k["centre"]) / b, rh * 1e3, "-", label="Reynolds")
        ax2.set_ylim(0, 4 * rh.min() * 1e3)
        ax2.set_xlabel("x / b")
        ax2.set_ylabel("h (mm)")
        ax2.legend()
        fig.suptitle(f"soft EHL, {out['frame']}")
        fig.tight_layout()
        fig.savefig(a.plot, dpi=110)


if __name__ == "__main__":
    main()
