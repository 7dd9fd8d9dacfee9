"""Several rendered frames (ryushi render's PNGs) as one picture, in a grid.

    /usr/bin/python3 tools/frame_strip.py OUT.png PNG [PNG ...] [--columns N]

For docs: e.g. `ryushi render RUN --frames 4,6,8,10` then this on RUN/render/pressure_0000{4,6,8}.png
and pressure_00010.png. Exit codes: 0 done, 2 bad input (a missing or unreadable PNG).
"""
import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg
import matplotlib.pyplot as plt


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("pngs", nargs="+")
    ap.add_argument("--columns", type=int, default=2)
    a = ap.parse_args()
    images = []
    for path in a.pngs:
        if not os.path.exists(path):
            print(f"frame_strip: no {path}", file=sys.stderr)
            return 2
        try:
            images.append(mpimg.imread(path))
        except (OSError, ValueError, SyntaxError) as e:
            print(f"frame_strip: {path}: {e}", file=sys.stderr)
            return 2
    columns = max(1, min(a.columns, len(images)))
    rows = math.ceil(len(images) / columns)
    height, width = images[0].shape[:2]
    scale = 6.0 / width
    fig, axes = plt.subplots(rows, columns, figsize=(columns * width * scale, rows * height * scale), squeeze=False)
    for k, ax in enumerate(axes.flat):
        ax.axis("off")
        if k < len(images):
            ax.imshow(images[k])
    fig.subplots_adjust(left=0, right=1, top=1, bottom=0, wspace=0.01, hspace=0.01)
    fig.savefig(a.out, dpi=100)
    print(f"frame_strip: {a.out} ({len(images)} frames)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
