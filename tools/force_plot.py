#!/usr/bin/python3
"""The force on a body from one or more runs against an experiment's series (issue 57).

Reads a force column of each run's probes.csv (`[[probe]] type = "force"`) and an experiment's
series (a CSV with '#' comment lines and a header: time in s, force in N), finds each one's first
contact (the first sample above --contact-level N), and reports, counted from that contact: the
peak within --peak-window s and the mean over --mean-window (start,end in s after the contact).
The experiment's time origin need not be the runs' (Yeh & Petroff's is not documented): the
series are compared from their first contacts. Draws every series, shifted to a common contact
time, into a PNG (--png).

  tools/force_plot.py --run wcsph=out/col/probes.csv --run isph=... --png column_force.png

Defaults are scenes/dam_break_column_3d.toml against tools/reference/yeh_petroff_column_force.csv.
"""
import argparse
import csv
import json


def read_series(path, time_column, force_column):
    with open(path) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    return [float(r[time_column]) for r in rows], [float(r[force_column]) for r in rows]


def contact_statistics(t, f, level, peak_window, mean_window):
    """(contact time, peak, time of the peak, mean over the window) from the first contact."""
    first = next((k for k, v in enumerate(f) if v > level), None)
    if first is None:
        return None
    t0 = t[first]
    peak = max((k for k in range(first, len(t)) if t[k] <= t0 + peak_window), key=lambda k: f[k])
    inside = [f[k] for k in range(len(t)) if t0 + mean_window[0] <= t[k] <= t0 + mean_window[1]]
    mean = sum(inside) / len(inside) if inside else float("nan")
    return t0, f[peak], t[peak], mean


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--run", action="append", required=True, help="LABEL=path/to/probes.csv (repeatable)")
    ap.add_argument("--column", default="column_fx", help="the force column of probes.csv")
    ap.add_argument("--experiment", default="tools/reference/yeh_petroff_column_force.csv")
    ap.add_argument("--contact-level", type=float, default=3.0, help="N: the first sample above it is the contact")
    ap.add_argument("--peak-window", type=float, default=0.15, help="s after the contact that hold the peak")
    ap.add_argument("--mean-window", default="0.15,0.35", help="start,end in s after the contact")
    ap.add_argument("--png", help="draw the series here")
    ap.add_argument("--json", help="write the records here")
    args = ap.parse_args()
    window = [float(v) for v in args.mean_window.split(",")]

    series = {"experiment": read_series(args.experiment, "t_s", "force_N")}
    for spec in args.run:
        label, path = spec.split("=", 1)
        series[label] = read_series(path, "time", args.column)
    reference = contact_statistics(*series["experiment"], args.contact_level, args.peak_window, window)
    records = []
    for label, (t, f) in series.items():
        stats = contact_statistics(t, f, args.contact_level, args.peak_window, window)
        if stats is None:
            print(f"{label:>14}: no contact (largest force {max(f):.2f} N)")
            continue
        t0, peak, t_peak, mean = stats
        rel = "" if label == "experiment" else f" ({100 * (mean / reference[3] - 1):+.1f}%)"
        print(f"{label:>14}: contact t = {t0:.3f} s, peak {peak:.2f} N at +{t_peak - t0:.3f} s, "
              f"mean over +{window[0]:g}..+{window[1]:g} s {mean:.2f} N{rel}")
        records.append({"label": label, "contact": t0, "peak": peak, "peak_after_contact": t_peak - t0, "mean": mean})
    if args.json:
        with open(args.json, "w") as out:
            json.dump(records, out, indent=1)
    if args.png:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(9, 4.5))
        t_ref = reference[0]
        for label, (t, f) in series.items():
            stats = contact_statistics(t, f, args.contact_level, args.peak_window, window)
            shift = t_ref - stats[0] if stats else 0.0
            style = dict(ls="", marker=".", ms=3, color="k") if label == "experiment" else dict(lw=0.9)
            ax.plot([v + shift for v in t], f, label=label if label == "experiment" else f"{label} (shifted {shift:+.3f} s)", **style)
        ax.axvspan(t_ref + window[0], t_ref + window[1], color="0.9", zorder=0, label="mean window")
        ax.set_xlabel("t (s), the experiment's origin; runs shifted to its first contact")
        ax.set_ylabel("force on the body (N)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(args.png, dpi=110)


if __name__ == "__main__":
    main()
