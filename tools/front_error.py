"""The dam-break criterion of tests/front_criterion.hpp for a run directory: the surge front
Z = x/a (probe `surge_front`) against Martin & Moyce (tools/reference/martin_moyce_1952_n2_2.csv)
after ONE fitted time-origin shift dT in [0, 0.30] (steps of 0.001), the largest relative error
for T <= 2.5, and the unshifted error beside it. T = n t sqrt(g/a), n^2 the column's height over
its width (Martin & Moyce's time; 2 for the default table).

    /usr/bin/python3 tools/front_error.py RUN_DIR [--a 0.25] [--g 9.81] [--n2 2]
        [--reference tools/reference/martin_moyce_1952_square.csv] [--t-max 2.5]

Prints `shift=<dT> error=<max error after the shift> unshifted=<max error without>`.
"""
import argparse
import csv
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def interpolate(xs, ys, at):
    for k in range(1, len(xs)):
        if xs[k] >= at:
            return ys[k - 1] + (ys[k] - ys[k - 1]) * (at - xs[k - 1]) / (xs[k] - xs[k - 1])
    return ys[-1]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("run")
    ap.add_argument("--a", type=float, default=0.25)
    ap.add_argument("--g", type=float, default=9.81)
    ap.add_argument("--n2", type=float, default=2.0, help="the column's height over its width")
    ap.add_argument("--reference", default=os.path.join(HERE, "reference", "martin_moyce_1952_n2_2.csv"))
    ap.add_argument("--t-max", type=float, default=2.5)
    args = ap.parse_args()
    scale = math.sqrt(args.a / (args.n2 * args.g))
    T, Z = [], []
    with open(os.path.join(args.run, "probes.csv")) as f:
        for row in csv.DictReader(f):
            T.append(float(row["time"]) / scale)
            Z.append(float(row["surge_front"]) / args.a)
    data = []
    with open(args.reference) as f:
        for line in f:
            if line[0] in "#T\n":
                continue
            t, z = map(float, line.split(","))
            if t <= args.t_max:
                data.append((t, z))

    def worst(shift):  # over the reference points the run reached
        return max(abs(interpolate(T, Z, t - shift) / z - 1) for t, z in data if t - shift <= T[-1])

    best = min((worst(0.001 * k), 0.001 * k) for k in range(301))
    print(f"shift={best[1]:.3f} error={100 * best[0]:.2f}% unshifted={100 * worst(0):.2f}%")


if __name__ == "__main__":
    main()
