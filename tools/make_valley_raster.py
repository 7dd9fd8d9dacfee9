#!/usr/bin/python3
"""Writes scenes/terrain/valley.asc, the synthetic terrain of scenes/valley_flood_swe.toml: a valley
4 m long and 2 m wide (cells of 0.1 m) that falls 2% along x, with a parabolic cross-section
(0.3 m higher at the sides than on the axis y = 1 m), a Gaussian knoll on its floor and a block of
NODATA cells (a rock outcrop: dry high ground in ryushi). Made by this script so that no terrain
data is downloaded; run it again to regenerate the file (it is deterministic).

    /usr/bin/python3 tools/make_valley_raster.py [OUT]
"""
import math
import sys

NCOLS, NROWS, CELL = 40, 20, 0.1
NODATA = -9999


def elevation(x, y):
    floor = 0.08 - 0.02 * x
    sides = 0.3 * ((y - 1.0) / 1.0) ** 2
    knoll = 0.05 * math.exp(-((x - 2.2) ** 2 + (y - 0.8) ** 2) / 0.15 ** 2)
    return floor + sides + knoll


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "scenes/terrain/valley.asc"
    lines = [f"ncols {NCOLS}", f"nrows {NROWS}", "xllcorner 0.0", "yllcorner 0.0", f"cellsize {CELL}",
             f"NODATA_value {NODATA}"]
    for r in range(NROWS):  # north (largest y) first
        y = (NROWS - 1 - r + 0.5) * CELL
        row = []
        for c in range(NCOLS):
            x = (c + 0.5) * CELL
            outcrop = 3.0 <= x <= 3.3 and 1.5 <= y <= 1.8
            row.append(str(NODATA) if outcrop else f"{elevation(x, y):.5f}")
        lines.append(" ".join(row))
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
