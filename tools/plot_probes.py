"""Probe columns of a ryushi run against time, one panel per column.

    /usr/bin/python3 tools/plot_probes.py OUT.png RUN COLUMN[,COLUMN...] [--scale S] [--ylabel TEXT] [--title TEXT]
                                          [--also RUN2 ...] [--labels L1,L2,...]

Reads RUN/probes.csv and draws each named column (times --scale, e.g. 1000 for millimetres)
against the time; with --also, the same columns of further runs (e.g. another resolution) on
the same panels, named by --labels. Exit codes: 0 done, 2 bad input (no probes.csv, unknown column).
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("png")
    ap.add_argument("run")
    ap.add_argument("columns")
    ap.add_argument("--scale", type=float, default=1.0)
    ap.add_argument("--ylabel", default="")
    ap.add_argument("--title", default="")
    ap.add_argument("--also", action="append", default=[])
    ap.add_argument("--labels", default="")
    a = ap.parse_args()
    names = a.columns.split(",")
    runs = [a.run] + a.also
    labels = a.labels.split(",") if a.labels else [os.path.basename(os.path.normpath(r)) for r in runs]
    if len(labels) != len(runs):
        print(f"plot_probes: {len(labels)} labels for {len(runs)} runs", file=sys.stderr)
        sys.exit(2)
    tables = []
    for run in runs:
        path = os.path.join(run, "probes.csv")
        if not os.path.exists(path):
            print(f"plot_probes: no {path}", file=sys.stderr)
            sys.exit(2)
        rows = list(csv.DictReader(open(path)))
        for n in names:
            if not rows or n not in rows[0]:
                print(f"plot_probes: no column '{n}' in {path} (has {list(rows[0]) if rows else []})", file=sys.stderr)
                sys.exit(2)
        tables.append(rows)
    fig, axes = plt.subplots(len(names), 1, figsize=(7, 2.6 * len(names)), sharex=True, squeeze=False)
    for ax, n in zip(axes[:, 0], names):
        for rows, label in zip(tables, labels):
            ax.plot([float(r["time"]) for r in rows], [float(r[n]) * a.scale for r in rows], "-", label=label)
        ax.set_ylabel(f"{n} {a.ylabel}".strip())
        ax.grid(alpha=0.3)
        if len(runs) > 1:
            ax.legend()
    axes[-1, 0].set_xlabel("t (s)")
    if a.title:
        axes[0, 0].set_title(a.title)
    fig.tight_layout()
    fig.savefig(a.png, dpi=100)
    print(a.png)


if __name__ == "__main__":
    main()
