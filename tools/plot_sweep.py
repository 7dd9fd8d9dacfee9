#!/usr/bin/python3
"""Draws a `ryushi sweep` table: an error column against wall time, the Pareto front marked.

    /usr/bin/python3 tools/plot_sweep.py SWEEP.csv OUT.png [--key K]... [--error COLUMN]

--key names the varied keys (the first columns of sweep.csv); one series per value of the last
varied key (one series when a single key varies), each point labelled with the other keys'
values (up to ten points; a larger sweep's points are in the table). Axes are logarithmic where
the values span a decade. --error picks the error column; by default the first column whose name ends in
"_error". The Pareto front joins the runs that no faster run beats in error. Exits 1 when the
table has no such column or no completed run.
"""
import argparse
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("csv")
    ap.add_argument("png")
    ap.add_argument("--key", action="append", default=[])
    ap.add_argument("--error", default="")
    a = ap.parse_args()
    rows = list(csv.DictReader(open(a.csv)))
    if not rows:
        sys.exit("plot_sweep: empty table")
    error = a.error or next((c for c in rows[0] if c.endswith("_error")), "")
    if not error or error not in rows[0]:
        sys.exit(f"plot_sweep: no error column ({error or 'none ending in _error'})")
    done = [r for r in rows if r["status"] == "completed" and r[error] not in ("", "nan")]
    if not done:
        sys.exit("plot_sweep: no completed run")
    keys = a.key
    series_key = keys[-1] if keys else None
    fig, ax = plt.subplots(figsize=(7.5, 5))
    groups = {}
    for r in done:
        groups.setdefault(r[series_key] if series_key else "runs", []).append(r)
    for value, rs in groups.items():
        rs.sort(key=lambda r: float(r["wall_time_s"]))
        xs = [float(r["wall_time_s"]) for r in rs]
        ys = [float(r[error]) for r in rs]
        ax.plot(xs, ys, "o-", label=f"{series_key} = {value}" if series_key else value)
        # Labels only where they stay readable; a larger sweep's points are in sweep.csv.
        for r, x, y in zip(rs, xs, ys):
            label = ", ".join(f"{k.split('.')[-1]}={r[k]}" for k in keys[:-1])
            if label and len(done) <= 10:
                ax.annotate(label, (x, y), textcoords="offset points", xytext=(4, 4), fontsize=7)
    # Pareto front: the runs no faster run beats.
    front, best = [], float("inf")
    for r in sorted(done, key=lambda r: float(r["wall_time_s"])):
        if float(r[error]) < best:
            best = float(r[error])
            front.append(r)
    ax.step([float(r["wall_time_s"]) for r in front], [float(r[error]) for r in front], "k--", where="post",
            lw=1, label="Pareto front")
    ax.scatter([float(r["wall_time_s"]) for r in front], [float(r[error]) for r in front], s=90,
               facecolors="none", edgecolors="k")
    # Log axes only where the values span a decade: a narrow range on a log axis crowds its labels.
    def spread(values):
        positive = [v for v in values if v > 0]
        return max(positive) / min(positive) if len(positive) == len(values) and positive else 1.0
    log_x = spread([float(r["wall_time_s"]) for r in done]) >= 10
    log_y = spread([float(r[error]) for r in done]) >= 10
    if log_x:
        ax.set_xscale("log")
    if log_y:
        ax.set_yscale("log")
    ax.grid(True, which="both", alpha=0.3)
    # Each label says its scale (the docs said "log axes" where they were linear).
    ax.set_xlabel("wall time (s, log scale)" if log_x else "wall time (s)")
    ax.set_ylabel(error + (" (log scale)" if log_y else ""))
    ax.set_title(f"{error} against wall time")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(a.png, dpi=90)
    # What the picture's axes are, for a terminal (and tools/test_paraview.sh).
    print(f"{a.png}: x {ax.get_xlabel()}, y {ax.get_ylabel()}")


if __name__ == "__main__":
    main()
