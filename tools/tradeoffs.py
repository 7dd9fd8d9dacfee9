#!/usr/bin/python3
"""Regenerates docs/tradeoffs.md: the speed-accuracy trade of ryushi's methods and settings,
measured with `ryushi sweep` on this machine (`make tradeoffs`).

    /usr/bin/python3 tools/tradeoffs.py [--build build] [--out out/tradeoffs] [--doc docs/tradeoffs.md]

Every study is a sweep (resumable: a re-run keeps the finished runs; delete --out to measure
anew). Runs go two at a time on one thread each (--jobs 2 --threads 1), so every wall time in
the document is one core's, measured under the same load. The figures in the document are the
run's own metrics ([[metric]] in the scenes: front_error, pressure_error).
"""
import argparse
import csv
import datetime
import math
import os
import subprocess
import sys

# (study, scene, varied keys, fixed overrides, error column)
DAM_END = "time.end=0.35"  # T = t sqrt(2 g / a) = 3.1 at a = 0.25 m: the front criterion's T <= 2.5 after a shift <= 0.3
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import poiseuille  # noqa: E402  (the channel's geometry at any l/d, as tests/poiseuille_test.cpp sets it)

# The Eulerian ISPH channel at l/d = 10, 16, 20 (one sweep per resolution: the geometry moves
# with d), each with the three viscous Laplacians, to t = 0.1 s (the start-up, where the profile
# still changes; profile_error is the scene's [[metric]]).
POISEUILLE_CELLS = (10, 16, 20)
STUDIES = [
    *[(f"operators_poiseuille_{cells}", "poiseuille_isph_2d.toml", ["method.viscous_laplacian=standard,corrected,sph2"],
       poiseuille.overrides(cells) + ["time.end=0.1"], "profile_error") for cells in POISEUILLE_CELLS],
    ("operators_hydrostatic", "hydrostatic_isph_2d.toml",
     ["method.ppe_laplacian=standard,corrected,sph2", "particles.spacing=0.025,0.0125,0.00625"],
     ["time.end=0.5"], "pressure_error"),
    ("mps_solver", "dam_break_mps_2d.toml",
     ["solver.tolerance=1e-3,1e-5,1e-8", "solver.cycle=v,w,sw", "solver.precision=double,mixed"],
     ["particles.spacing=0.0125", DAM_END], "front_error"),
    ("wcsph_sound_speed", "dam_break_2d.toml",
     ["method.delta=0,0.1", "material.sound_speed_factor=5,10,20"],
     ["particles.spacing=0.0125", DAM_END], "front_error"),
    ("dam_break_wcsph", "dam_break_2d.toml", ["particles.spacing=0.025,0.0125,0.00625"], [DAM_END], "front_error"),
    ("dam_break_mps", "dam_break_mps_2d.toml", ["particles.spacing=0.025,0.0125,0.00625"], [DAM_END], "front_error"),
    ("dam_break_isph", "dam_break_isph_2d.toml", ["particles.spacing=0.025,0.0125,0.00625"], [DAM_END], "front_error"),
    ("hydrostatic_wcsph", "hydrostatic_2d.toml", ["particles.spacing=0.025,0.0125,0.00625"], ["time.end=0.5"],
     "pressure_error"),
    ("hydrostatic_mps", "hydrostatic_mps_2d.toml", ["particles.spacing=0.025,0.0125,0.00625"], ["time.end=0.5"],
     "pressure_error"),
    ("hydrostatic_isph", "hydrostatic_isph_2d.toml", ["particles.spacing=0.025,0.0125,0.00625"], ["time.end=0.5"],
     "pressure_error"),
    ("swe_splitting", "dam_break_ritter_swe.toml",
     ["swe.momentum=mps,sph", "splitting.enabled=false,true", "particles.spacing=0.1,0.05,0.025"],
     [], "ritter_error"),
]


def run_sweep(build, out, study):
    name, scene, vary, sets, error = study
    cmd = [os.path.join(build, "ryushi"), "sweep", os.path.join("scenes", scene), "--out", os.path.join(out, name),
           "--jobs", "2", "--threads", "1", "--error", error, "--quiet"]
    for v in vary:
        cmd += ["--vary", v]
    for s in sets:
        cmd += ["--set", s]
    print("tradeoffs:", " ".join(cmd), flush=True)
    # Exit 3 means some run failed numerically: the table says which, the study goes on.
    code = subprocess.call(cmd)
    if code not in (0, 3):
        sys.exit(f"tradeoffs: sweep {name} exited {code}")
    with open(os.path.join(out, name, "sweep.csv")) as f:
        return list(csv.DictReader(f))


def keys_of(study):
    return [v.split("=")[0] for v in study[2]]


def short(key):
    """A varied key's name in tables: its last part, or its section for an on/off switch."""
    section, _, name = key.rpartition(".")
    return section.split(".")[-1] if name == "enabled" else name


def fmt(x, digits=3):
    if x in ("", None):
        return "-"
    v = float(x)
    if math.isnan(v):
        return "nan"
    return f"{v:.{digits}g}"


def table(rows, keys, error, extra=()):
    head = [short(k) for k in keys] + ["status", "wall s", "steps", "particles", error] + [e[1] for e in extra]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for r in rows:
        cells = [r[k] for k in keys] + [r["status"], fmt(r["wall_time_s"]), r["steps"], r["particles"],
                                         fmt(r.get(error, ""))]
        cells += [fmt(r.get(e[0], "")) for e in extra]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def completed(rows, error):
    out = []
    for r in rows:
        if r["status"] != "completed" or r.get(error, "") in ("", "nan"):
            continue
        if math.isnan(float(r[error])):
            continue
        out.append(r)
    return out


def fastest_within(candidates, budget):
    """(label, row) of the fastest run whose error is within the budget, or None."""
    ok = [(float(r["wall_time_s"]), label, r) for label, r, err in candidates if err <= budget]
    if not ok:
        return None
    ok.sort(key=lambda t: t[0])
    return ok[0][1], ok[0][2]


def plot_series(series, ylabel, title, png):
    """Error against wall time on log axes: series = [(label, [(wall, error, point label), ...]), ...]."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for label, pts in series:
        pts = sorted(pts)
        ax.loglog([p[0] for p in pts], [p[1] for p in pts], "o-", label=label)
        for x, y, text in pts:
            ax.annotate(text, (x, y), textcoords="offset points", xytext=(4, 3), fontsize=7)
    ax.set_xlabel("wall time, s (one core)")
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(framealpha=0.6)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def plot_methods(results, names, error, png, title):
    series = [(name.split("_")[-1].upper(),
               [(float(r["wall_time_s"]), float(r[error]), f"d={r['particles.spacing']}")
                for r in completed(results[name], error)]) for name in names]
    plot_series(series, error, title, png)


def plot_poiseuille(results, png):
    series = [(lap, [(float(r["wall_time_s"]), float(r["profile_error"]), f"l/d={cells}")
                     for cells in POISEUILLE_CELLS
                     for r in completed(results[f"operators_poiseuille_{cells}"], "profile_error")
                     if r["method.viscous_laplacian"] == lap])
              for lap in ("standard", "corrected", "sph2")]
    plot_series(series, "profile_error", "Poiseuille start-up (ISPH, t = 0.1 s): viscous Laplacian x resolution", png)


def at_equal_time(rows, error, wall):
    """log-log interpolation of the error at a wall time inside the sweep's range, else None."""
    pts = sorted((float(r["wall_time_s"]), float(r[error])) for r in completed(rows, error))
    for (t0, e0), (t1, e1) in zip(pts, pts[1:]):
        if t0 <= wall <= t1 and e0 > 0 and e1 > 0 and t1 > t0:
            w = (math.log(wall) - math.log(t0)) / (math.log(t1) - math.log(t0))
            return math.exp((1 - w) * math.log(e0) + w * math.log(e1))
    return None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default="build")
    ap.add_argument("--out", default="out/tradeoffs")
    ap.add_argument("--doc", default="docs/tradeoffs.md")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    os.makedirs("docs/img", exist_ok=True)
    results = {s[0]: run_sweep(a.build, a.out, s) for s in STUDIES}
    by_name = {s[0]: s for s in STUDIES}
    for name in ("operators_hydrostatic", "mps_solver", "wcsph_sound_speed", "swe_splitting"):
        cmd = [sys.executable, os.path.join(os.path.dirname(os.path.abspath(__file__)), "plot_sweep.py"),
               os.path.join(a.out, name, "sweep.csv"), f"docs/img/tradeoffs_{name}.png", "--error", by_name[name][4]]
        for k in keys_of(by_name[name]):
            cmd += ["--key", k]
        subprocess.check_call(cmd)
    plot_methods(results, ["dam_break_wcsph", "dam_break_mps", "dam_break_isph"], "front_error",
                 "docs/img/tradeoffs_dam_break_methods.png", "Dam break a x 2a to t = 0.35 s: front error vs wall time")
    plot_methods(results, ["hydrostatic_wcsph", "hydrostatic_mps", "hydrostatic_isph"], "pressure_error",
                 "docs/img/tradeoffs_hydrostatic_methods.png", "Resting tank to t = 0.5 s: pressure error vs wall time")

    doc = []
    w = doc.append
    w("# The speed-accuracy trade, measured\n")
    w(f"Regenerated by `make tradeoffs` (tools/tradeoffs.py, {datetime.date.today()}; about three minutes on this "
      "2-core machine). Every study is a `ryushi sweep`; runs go two at a time on one thread each, so each wall "
      "time is one core's under the same load. Errors are the scenes' own `[[metric]]` values: `front_error` is "
      "the largest relative error of the surge front against Martin & Moyce (n^2 = 2) for T <= 2.5 after one "
      "fitted time-origin shift in [0, 0.30] (the criterion of the ISPH issue); `pressure_error` is the relative "
      "L2 error of the fluid pressure against rho g depth at the end. The raw tables are in out/tradeoffs/*/"
      "sweep.csv (with each system's share of the time).\n")

    w("## Resolution x operator order: the Poiseuille channel (ISPH, Eulerian)\n")
    w("The viscous term's Laplacian (ISPH paper eq. 15): standard (Morris), corrected or SPH(2), at l/d = "
      + ", ".join(str(c) for c in POISEUILLE_CELLS) + ", to t = 0.1 s; profile_error is the L2 error of the "
      "velocity across the channel against Morris, Fox & Zhu's start-up series, relative to the centreline "
      "speed.\n")
    lines = ["| viscous_laplacian | l/d | status | wall s | steps | particles | profile_error |",
             "|---|---|---|---|---|---|---|"]
    for cells in POISEUILLE_CELLS:
        for r in results[f"operators_poiseuille_{cells}"]:
            lines.append(f"| {r['method.viscous_laplacian']} | {cells} | {r['status']} | {fmt(r['wall_time_s'])} | "
                         f"{r['steps']} | {r['particles']} | {fmt(r.get('profile_error', ''))} |")
    w("\n".join(lines) + "\n")
    ratios = []
    for cells in POISEUILLE_CELLS:
        e = {r["method.viscous_laplacian"]: float(r["profile_error"])
             for r in completed(results[f"operators_poiseuille_{cells}"], "profile_error")}
        t = {r["method.viscous_laplacian"]: float(r["wall_time_s"])
             for r in completed(results[f"operators_poiseuille_{cells}"], "profile_error")}
        if {"standard", "corrected", "sph2"} <= e.keys():
            ratios.append((cells, e["standard"] / e["corrected"], abs(e["sph2"] / e["corrected"] - 1),
                           t["corrected"] / t["standard"], e["standard"]))
    if ratios:
        w("The second-order Laplacians cut the error by " + ", ".join(f"{r[1]:.0f}x" for r in ratios)
          + " at l/d = " + ", ".join(str(r[0]) for r in ratios) + " for " + ", ".join(f"{r[3]:.2f}x" for r in ratios)
          + " the wall time (corrected against standard); corrected "
          "and SPH(2) agree to " + f"{max(r[2] for r in ratios):.1e}" + " (relative): on these complete, "
          "lattice-like stencils both are second-order consistent. The standard (Morris) Laplacian's error falls "
          "only from " + fmt(ratios[0][4]) + " to " + fmt(ratios[-1][4]) + " over the same resolutions.\n")
    plot_poiseuille(results, "docs/img/tradeoffs_operators_poiseuille.png")
    w("![profile error against wall time](img/tradeoffs_operators_poiseuille.png)\n")

    w("## Resolution x operator order: the resting ISPH tank\n")
    w("The ISPH pressure equation's Laplacian: standard (Morris), corrected (Fatehi-Manzari, the ISPH paper's "
      "eqs. 11-14) or SPH(2) (the trace of the second-order Hessian); d = 0.025, 0.0125, 0.00625 m (H/d = 20, "
      "40, 80) to t = 0.5 s.\n")
    s = by_name["operators_hydrostatic"]
    w(table(results[s[0]], keys_of(s), s[4]) + "\n")
    w("The pressure at rest is linear in depth, and the corrected and SPH(2) Laplacians are both exact for "
      "linear fields: the two give the same solution, and the resting tank cannot tell them apart. The standard "
      "Laplacian is not exact for it near the surface and the walls.\n")
    w("![pressure error against wall time](img/tradeoffs_operators_hydrostatic.png)\n")

    w("## Solver tolerance, cycle and precision: the MPS dam break\n")
    w("The S-W/V/W-cycle bucket multigrid preconditioning CG, in double or mixed precision, at three relative "
      "tolerances; a/d = 20, to t = 0.35 s. `linear_solve` is that system's share of the run time.\n")
    s = by_name["mps_solver"]
    w(table(results[s[0]], keys_of(s), s[4], extra=[("share_linear_solve", "linear_solve share"),
                                                   ("front_error_shift", "shift")]) + "\n")
    rows = completed(results[s[0]], s[4])
    if rows:
        errs = [float(r[s[4]]) for r in rows]
        walls = [float(r["wall_time_s"]) for r in rows]
        shares = [float(r["share_linear_solve"]) for r in rows]
        fastest = min(rows, key=lambda r: float(r["wall_time_s"]))
        w(f"Across the {len(rows)} settings the front error stays between {min(errs):.4g} and {max(errs):.4g}, while "
          f"the wall time goes from {min(walls):.3g} to {max(walls):.3g} s and the linear solve's share from "
          f"{min(shares):.2f} to {max(shares):.2f}: the front does not see the solver's tolerance down to 1e-3, so "
          f"the fastest setting ({', '.join(f'{short(k)} = {fastest[k]}' for k in keys_of(s))}) loses "
          "nothing in the front (only the front is measured here: a pressure probe or an impact load may see "
          "the tolerance where the front does not).\n")
    w("![front error against wall time](img/tradeoffs_mps_solver.png)\n")

    w("## WCSPH sound-speed factor and delta-SPH\n")
    w("c0 = factor sqrt(2 g H) and the delta-SPH diffusion coefficient; a/d = 20, to t = 0.35 s. The step is "
      "acoustic (dt ~ h / c0), so the wall time scales with the factor.\n")
    s = by_name["wcsph_sound_speed"]
    w(table(results[s[0]], keys_of(s), s[4], extra=[("max_density_deviation", "max density deviation"),
                                                   ("front_error_shift", "shift")]) + "\n")
    rows = {(r["method.delta"], r["material.sound_speed_factor"]): r for r in completed(results[s[0]], s[4])}
    if ("0.1", "5") in rows and ("0.1", "20") in rows:
        lo, hi = rows[("0.1", "5")], rows[("0.1", "20")]
        w(f"With delta = 0.1, going from factor 5 to 20 takes {int(hi['steps']) / int(lo['steps']):.1f}x the steps and "
          f"{float(hi['wall_time_s']) / float(lo['wall_time_s']):.1f}x the wall time, brings the largest density "
          f"deviation from {fmt(lo['max_density_deviation'])} to {fmt(hi['max_density_deviation'])} and the front "
          f"error from {fmt(lo['front_error'])} to {fmt(hi['front_error'])}."
          + (f" The default (10) keeps the density within {100 * float(rows[('0.1', '10')]['max_density_deviation']):.1f}%."
             if ("0.1", "10") in rows else "") + "\n")
    w("![front error against wall time](img/tradeoffs_wcsph_sound_speed.png)\n")

    w("## WCSPH, MPS and ISPH side by side\n")
    w("Each method's shipped scene (its own tuned settings) at d = 0.025, 0.0125, 0.00625 m.\n")
    w("### Dam break (a/d = 10, 20, 40; to t = 0.35 s)\n")
    for name in ("dam_break_wcsph", "dam_break_mps", "dam_break_isph"):
        s = by_name[name]
        w(f"**{name.split('_')[-1].upper()}** (scenes/{s[1]})\n")
        w(table(results[name], keys_of(s), s[4], extra=[("front_error_shift", "shift"),
                                                       ("front_error_unshifted", "unshifted")]) + "\n")
    w("![dam break: front error against wall time](img/tradeoffs_dam_break_methods.png)\n")
    w("### Resting tank (H/d = 20, 40, 80; to t = 0.5 s)\n")
    for name in ("hydrostatic_wcsph", "hydrostatic_mps", "hydrostatic_isph"):
        s = by_name[name]
        w(f"**{name.split('_')[-1].upper()}** (scenes/{s[1]})\n")
        w(table(results[name], keys_of(s), s[4]) + "\n")
    w("![resting tank: pressure error against wall time](img/tradeoffs_hydrostatic_methods.png)\n")

    w("### At equal wall time\n")
    w("Each method's error interpolated (log-log, between its two neighbouring resolutions) at a common wall "
      "time; '-' where that time lies outside the method's sweep.\n")
    for flow, names, error in (("dam break front_error", ["dam_break_wcsph", "dam_break_mps", "dam_break_isph"],
                                "front_error"),
                               ("resting tank pressure_error",
                                ["hydrostatic_wcsph", "hydrostatic_mps", "hydrostatic_isph"], "pressure_error")):
        walls = [0.3, 1.0, 3.0, 10.0, 30.0]
        lines = ["| wall time (s) | WCSPH | MPS | ISPH |", "|---|---|---|---|"]
        for wall in walls:
            values = [at_equal_time(results[n], error, wall) for n in names]
            if all(v is None for v in values):
                continue  # a time outside every method's sweep says nothing
            lines.append(f"| {wall:g} | " + " | ".join("-" if v is None else f"{v:.3g}" for v in values) + " |")
        w(f"**{flow}**\n")
        w("\n".join(lines) + "\n")

    w("## Shallow water: momentum form x particle splitting x resolution on Ritter's dam break\n")
    w("Method swe, h0 = 0.25 m released onto a dry bed, to t = 0.5 s; ritter_error is sum |h - h_Ritter| / "
      "sum h_Ritter over the particles downstream of the dam (docs/swe.md), ritter_error_front the front's lag "
      "behind 2 sqrt(g h0) t relative to that run.\n")
    s = by_name["swe_splitting"]
    w(table(results[s[0]], keys_of(s), s[4], extra=[("ritter_error_front", "front lag"),
                                                   ("ritter_error_whole", "whole wave")]) + "\n")
    w("![Ritter depth error against wall time](img/tradeoffs_swe_splitting.png)\n")

    w("## For an error budget of X on this kind of flow, pick Y\n")
    w("The fastest measured run within each budget (from the tables above; wall time on one core).\n")
    lines = ["| flow | error budget | pick | wall s | error |", "|---|---|---|---|---|"]

    def candidates(names, error, keys):
        out = []
        for n in names:
            for r in completed(results[n], error):
                label = {"mps_solver": "MPS", "wcsph_sound_speed": "WCSPH", "operators_hydrostatic": "ISPH"}.get(
                    n, n.split("_")[-1].upper())
                label += " " + ", ".join(f"{short(k)} = {r[k]}" for k in keys(n))
                out.append((label, r, float(r[error])))
        return out

    dam = candidates(["dam_break_wcsph", "dam_break_mps", "dam_break_isph", "mps_solver", "wcsph_sound_speed"],
                     "front_error", lambda n: keys_of(by_name[n]))
    tank = candidates(["hydrostatic_wcsph", "hydrostatic_mps", "hydrostatic_isph", "operators_hydrostatic"],
                      "pressure_error", lambda n: keys_of(by_name[n]))
    swe = candidates(["swe_splitting"], "ritter_error", lambda n: keys_of(by_name[n]))
    swe = [("SWE " + label.split(" ", 1)[1], r, e) for label, r, e in swe]
    for flow, cands, error, budgets in (("violent free surface (dam break front)", dam, "front_error", [0.05, 0.03, 0.02]),
                                       ("still water (hydrostatic pressure)", tank, "pressure_error", [0.01, 1e-3, 1e-4]),
                                       ("shallow water onto a dry bed (Ritter depth)", swe, "ritter_error", [0.4, 0.2, 0.1])):
        for b in budgets:
            pick = fastest_within(cands, b)
            if pick is None:
                lines.append(f"| {flow} | {b:g} | none measured | - | - |")
            else:
                label, r = pick
                lines.append(f"| {flow} | {b:g} | {label} | {fmt(r['wall_time_s'])} | {fmt(r[error])} |")
    w("\n".join(lines) + "\n")
    with open(a.doc, "w") as f:
        f.write("\n".join(doc))
    print("tradeoffs: wrote", a.doc)


if __name__ == "__main__":
    main()
