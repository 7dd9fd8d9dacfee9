#!/usr/bin/python3
"""Wall pressure sensors of one or more runs against an experiment (issue 57).

Reads probes.csv of each run (columns written by `[[probe]] type = "wall_pressure"`), scales
them as P* = p / (rho g H) against t* = t sqrt(g / H), and for each sensor reports the first
impact: its arrival (the first sample above 0.2 rho g H), its peak (the largest sample within
`--impact-window` t* of the arrival) and the time of that peak, against the experiment's peak
statistics (a CSV of z_mm, median, 2.5% and 97.5% in mbar: tools/reference/lobovsky_2014_h300_peaks.csv)
and, where the experiment's pointwise percentile series is given for one sensor, the mean of P*
over a window after the first impact against the series' median mean. Draws every sensor's
series (and the experiment's band) into a PNG.

  tools/sensor_plot.py --run wcsph=out/lob/probes.csv --run isph=... --png sensors.png

Defaults are the Lobovsky et al. (2014) H = 300 mm case of scenes/dam_break_lobovsky_2d.toml. Their
80 mm sensor's peak statistic is most likely the run-up's return at t* ~ 6 (in the one published
run's record its first impact reaches 0.58, the record 0.84 at t* 5.95): compare its record max.
Prints one line per run and sensor; --json writes the same as a list of records.
"""
import argparse
import csv
import json
import math


def read_table(path):
    """A CSV with '#' comment lines and a header: {column: [floats]}."""
    with open(path) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def first_impact(t, p, window, arrival_level=0.2):
    """(arrival t*, peak P*, t* of the peak) of the first impact, or None if none arrives."""
    arrival = next((k for k, v in enumerate(p) if v > arrival_level), None)
    if arrival is None:
        return None
    inside = [k for k in range(arrival, len(t)) if t[k] <= t[arrival] + window]
    peak = max(inside, key=lambda k: p[k])
    return t[arrival], p[peak], t[peak]


def window_mean(t, p, lo, hi):
    values = [v for s, v in zip(t, p) if lo <= s <= hi]
    return sum(values) / len(values) if values else float("nan")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--run", action="append", required=True, help="LABEL=path/to/probes.csv (repeatable)")
    ap.add_argument("--height", type=float, default=0.3, help="H, m (the scale of t* and P*)")
    ap.add_argument("--density", type=float, default=997.0)
    ap.add_argument("--gravity", type=float, default=9.81)
    ap.add_argument("--sensors", default="sensor_1:3,sensor_2:15,sensor_3:30,sensor_4:80",
                    help="probe:height_mm pairs, matched to the peaks table's z_mm")
    ap.add_argument("--peaks", default="tools/reference/lobovsky_2014_h300_peaks.csv")
    ap.add_argument("--series", default="sensor_2=tools/reference/lobovsky_2014_h300_sensor2_percentiles.csv",
                    help="probe=CSV of t_star, p2_5, median, p97_5 ('' for none)")
    ap.add_argument("--impact-window", type=float, default=0.5, help="t* after the arrival that holds the first peak")
    ap.add_argument("--mean-window", default="2.8,5.5",
                    help="t* range of the mean after the first impact (until the run-up returns)")
    ap.add_argument("--png", help="draw the series here")
    ap.add_argument("--json", help="write the records here")
    a = ap.parse_args()

    scale_p = a.density * a.gravity * a.height
    scale_t = math.sqrt(a.height / a.gravity)
    sensors = [(s.split(":")[0], float(s.split(":")[1])) for s in a.sensors.split(",")]
    peaks = read_table(a.peaks)
    mbar = 100.0 / scale_p  # mbar -> P*
    band = {z: (m * mbar, lo * mbar, hi * mbar)
            for z, m, lo, hi in zip(peaks["z_mm"], peaks["median_mbar"], peaks["p2_5_mbar"], peaks["p97_5_mbar"])}
    series_probe, series = None, None
    if a.series:
        series_probe, path = a.series.split("=")
        series = read_table(path)
    lo, hi = (float(v) for v in a.mean_window.split(","))

    records = []
    runs = []
    for spec in a.run:
        label, path = spec.split("=", 1)
        table = read_table(path)
        t = [v / scale_t for v in table["time"]]
        runs.append((label, t, {name: [v / scale_p for v in table[name]] for name, _ in sensors}))
        for name, z in sensors:
            p = runs[-1][2][name]
            r = {"run": label, "sensor": name, "z_mm": z}
            impact = first_impact(t, p, a.impact_window)
            if impact:
                r.update(arrival=impact[0], peak=impact[1], peak_time=impact[2])
            r["record_max"] = max(p)
            if z in band:
                r.update(exp_median=band[z][0], exp_p2_5=band[z][1], exp_p97_5=band[z][2])
                if impact:
                    r["in_band"] = band[z][1] <= impact[1] <= band[z][2]
            if series and name == series_probe:
                median = series["median"]
                r["exp_peak_time"] = series["t_star"][max(range(len(median)), key=lambda k: median[k])]
                r["exp_mean"] = window_mean(series["t_star"], median, lo, hi)
                r["mean"] = window_mean(t, p, lo, hi)
            records.append(r)
            line = f"{label:>10} {name:>9} z = {z:4.0f} mm: "
            line += (f"arrival t* {r['arrival']:.3f}, peak {r['peak']:.2f} at t* {r['peak_time']:.3f}"
                     if impact else "no impact")
            line += f" (record max {r['record_max']:.2f})"
            if "exp_median" in r:
                line += f"; experiment {r['exp_median']:.2f} [{r['exp_p2_5']:.2f}, {r['exp_p97_5']:.2f}]"
                if impact:
                    line += " in band" if r["in_band"] else " OUT of band"
            if "exp_mean" in r:
                line += (f"; peak time of the median series {r['exp_peak_time']:.3f}; mean over t* {lo}-{hi}: "
                         f"{r['mean']:.3f} against {r['exp_mean']:.3f} ({100 * (r['mean'] / r['exp_mean'] - 1):+.1f}%)")
            print(line)
    if a.json:
        with open(a.json, "w") as f:
            json.dump(records, f, indent=1)
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axes = plt.subplots(len(sensors), 1, figsize=(9, 2.6 * len(sensors)), sharex=True)
        for ax, (name, z) in zip(axes, sensors):
            if series and name == series_probe:
                ax.fill_between(series["t_star"], series["p2_5"], series["p97_5"], color="0.8",
                                label="experiment 2.5-97.5%")
                ax.plot(series["t_star"], series["median"], color="k", lw=0.8, label="experiment median")
            if z in band:
                ax.axhspan(band[z][1], band[z][2], color="tab:green", alpha=0.15, label="peak 2.5-97.5%")
            for label, t, p in runs:
                ax.plot(t, p[name], lw=0.7, label=label)
            peak_hi = max([band.get(z, (0, 0, 1))[2]] + [max(p[name]) for _, _, p in runs])
            ax.set_ylim(-0.5, min(peak_hi * 1.1, 6))
            ax.set_xlim(2, 7)
            ax.set_ylabel(f"P* ({name}, {z:g} mm)")
            ax.grid(alpha=0.3)
        axes[0].legend(fontsize=7, ncol=3, loc="upper right")
        axes[-1].set_xlabel("t* = t sqrt(g/H)")
        fig.tight_layout()
        fig.savefig(a.png, dpi=100)


if __name__ == "__main__":
    main()
