"""Pictures of a ryushi run without ParaView: PNGs of frames coloured by a field, and an MP4.

    /usr/bin/python3 tools/render.py OUT [--field pressure] [--frames all|last|N[,N...]]
                                         [--movie] [--slice AXIS=VALUE] [--range LO,HI] [--dest DIR]
(`ryushi render OUT ...` runs this script.)

Writes DIR/FIELD_NNNNN.png (DIR defaults to OUT/render) for each chosen frame: fluid particles
as discs of the particle spacing, coloured by the field (the magnitude of a vector field) with a
colour bar, walls in grey, the simulated time in the title. With --movie, DIR/FIELD.mp4 of all
frames at 10 frames per second (Debian's ffmpeg, H.264). A 3D run is drawn in the x-z plane:
every particle projected (default), or with --slice y=0.1 only those within one spacing of that
plane. The colour range is the 1st-99th percentile of the field over the drawn frames, the same
for every frame, unless --range gives it.

Exit codes: 0 done, 2 bad input (no frames, unknown field, bad option, --movie without ffmpeg),
4 the pictures could not be written (a read-only or full DIR), 1 internal error.
"""
import argparse
import glob
import os
import shutil
import subprocess
import sys

try:
    import h5py
    import matplotlib
    import numpy as np

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import EllipseCollection
except ImportError as missing:
    print(f"ryushi render: {missing}: install Debian's python3-h5py, python3-matplotlib and python3-numpy "
          "(`make py-deps`)", file=sys.stderr)
    sys.exit(1)

UNITS = {"pressure": "Pa", "density": "kg/m^3", "velocity": "m/s", "acceleration": "m/s^2", "mass": "kg"}


def bad_input(message):
    print(f"ryushi render: {message}", file=sys.stderr)
    sys.exit(2)


def cannot_write(path, error):
    # A read-only or full folder ended in a Python traceback.
    print(f"ryushi render: could not write {path}: {error.strerror or error}", file=sys.stderr)
    sys.exit(4)


def frame_files(out):
    files = sorted(glob.glob(os.path.join(out, "frames", "frame_*.h5")))
    if not files:
        bad_input(f"{out}: no frames (expected {os.path.join(out, 'frames', 'frame_NNNNN.h5')})")
    return files


def choose(files, which):
    if which == "all":
        return files
    if which == "last":
        return files[-1:]
    try:
        picks = [int(k) for k in which.split(",")]
    except ValueError:
        bad_input(f"--frames {which}: expected all, last or frame numbers like 0,10,20")
    for k in picks:
        if not 0 <= k < len(files):
            bad_input(f"--frames {which}: frame {k} does not exist (0..{len(files) - 1})")
    return [files[k] for k in picks]


def summary_of(out):
    """(scene name, particle spacing) from summary.json; (directory name, None) without one."""
    import json

    try:
        with open(os.path.join(out, "summary.json")) as f:
            s = json.load(f)
        return s["scene"], float(s["parameters"]["spacing"])
    except (OSError, KeyError, ValueError):
        return os.path.basename(os.path.normpath(out)), None


def load(path, field, plane_axis, slice_value, spacing):
    with h5py.File(path, "r") as h:
        if field not in h:
            bad_input(f"{path}: no field '{field}' (has {', '.join(sorted(k for k in h if k != 'connectivity'))})")
        x = h["position"][:]
        kind = h["kind"][:]
        value = h[field][:]
        time = float(h.attrs["time"])
    if value.ndim > 1:
        value = np.linalg.norm(value.reshape(len(value), -1), axis=1)
    dim3 = np.any(x[:, 2] != 0)
    if dim3:
        keep = np.ones(len(x), bool)
        if slice_value is not None:
            keep = np.abs(x[:, plane_axis] - slice_value) <= spacing
        horizontal, vertical = x[keep, 0], x[keep, 2]
        return horizontal, vertical, kind[keep], value[keep], time, True
    return x[:, 0], x[:, 1], kind, value, time, False


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out")
    ap.add_argument("--field", default="pressure")
    ap.add_argument("--frames", default="all")
    ap.add_argument("--movie", action="store_true")
    ap.add_argument("--slice", default=None, help="3D: AXIS=VALUE, e.g. y=0.1")
    ap.add_argument("--range", default=None, help="LO,HI of the colour bar")
    ap.add_argument("--dest", default=None)
    a = ap.parse_args()

    if not os.path.isdir(a.out):
        bad_input(f"{a.out}: no such output directory")
    # Before any picture: it rendered every PNG and then failed for want of ffmpeg.
    ffmpeg = shutil.which("ffmpeg")
    if a.movie and ffmpeg is None:
        bad_input("--movie needs ffmpeg, which is not installed (Debian package ffmpeg: `make render-deps` "
                  "installs it); without --movie the PNGs need only Python's packages")
    files = frame_files(a.out)
    chosen = files if a.movie else choose(files, a.frames)
    dest = a.dest or os.path.join(a.out, "render")
    try:
        os.makedirs(dest, exist_ok=True)
        probe = os.path.join(dest, ".ryushi-render-probe")
        with open(probe, "w"):
            pass
        os.remove(probe)
    except OSError as e:
        cannot_write(dest, e)
    name, spacing = summary_of(a.out)
    plane_axis, slice_value = 1, None
    if a.slice:
        try:
            axis, value = a.slice.split("=")
            plane_axis = {"x": 0, "y": 1, "z": 2}[axis.strip()]
            slice_value = float(value)
        except (ValueError, KeyError):
            bad_input(f"--slice {a.slice}: expected AXIS=VALUE with AXIS x, y or z")
        if spacing is None:
            bad_input(f"--slice needs the spacing from {os.path.join(a.out, 'summary.json')}")

    frames = [load(f, a.field, plane_axis, slice_value, spacing) for f in chosen]
    if a.range:
        try:
            lo, hi = (float(v) for v in a.range.split(","))
        except ValueError:
            bad_input(f"--range {a.range}: expected LO,HI")
    else:
        fluid_values = np.concatenate([f[3][f[2] == 0] for f in frames] or [np.zeros(1)])
        lo, hi = np.percentile(fluid_values, [1, 99]) if len(fluid_values) else (0.0, 1.0)
        if hi <= lo:
            hi = lo + 1.0
    # One extent for all frames, so a movie does not jump.
    xs = np.concatenate([f[0] for f in frames])
    ys = np.concatenate([f[1] for f in frames])
    pad = 0.02 * max(np.ptp(xs), np.ptp(ys), 1e-12)
    extent = (xs.min() - pad, xs.max() + pad, ys.min() - pad, ys.max() + pad)
    d = spacing or 0.01 * max(np.ptp(xs), np.ptp(ys))

    written = []
    for (h, v, kind, value, time, dim3), path in zip(frames, chosen):
        # Axes about 6.2 inches wide (the colour bar takes the rest), as tall as the aspect needs.
        width = 8.0
        height = min(max(6.2 * (extent[3] - extent[2]) / (extent[1] - extent[0]) + 1.1, 3.0), 12.0)
        fig, ax = plt.subplots(figsize=(width, height), dpi=100, layout="constrained")
        ax.set_xlim(extent[0], extent[1])
        ax.set_ylim(extent[2], extent[3])
        ax.set_aspect("equal")
        wall = kind != 0
        fluid = ~wall
        # Discs of diameter d in data units, whatever the figure size.
        for mask, colours in ((wall, None), (fluid, value)):
            if not mask.any():
                continue
            discs = EllipseCollection(np.full(mask.sum(), d), np.full(mask.sum(), d), np.zeros(mask.sum()),
                                      units="xy", offsets=np.c_[h[mask], v[mask]], offset_transform=ax.transData)
            if colours is None:
                discs.set_facecolor("0.6")
            else:
                discs.set_array(colours[mask])
                discs.set_cmap("viridis")
                discs.set_clim(lo, hi)
                bar = fig.colorbar(discs, ax=ax, shrink=0.8)
                magnitude = " magnitude" if a.field in ("velocity", "acceleration") else ""
                unit = f" ({UNITS[a.field]})" if a.field in UNITS else ""
                bar.set_label(a.field + magnitude + unit)
            discs.set_edgecolor("none")
            ax.add_collection(discs)
        view = " (x-z projection)" if dim3 and slice_value is None else (f" ({a.slice} slice)" if dim3 else "")
        ax.set_title(f"{name}: t = {time:.4g} s{view}")
        ax.set_xlabel("x (m)")
        ax.set_ylabel("z (m)" if dim3 else "y (m)")
        stem = os.path.splitext(os.path.basename(path))[0].replace("frame", a.field)
        png = os.path.join(dest, stem + ".png")
        try:
            fig.savefig(png + ".tmp.png")
            os.replace(png + ".tmp.png", png)
        except OSError as e:
            cannot_write(png, e)
        plt.close(fig)
        written.append(png)
    for png in written[-3:] if not a.movie else []:
        print(png)

    if a.movie:
        mp4 = os.path.join(dest, a.field + ".mp4")
        pattern = os.path.join(dest, a.field + "_%05d.png")
        cmd = [ffmpeg, "-y", "-loglevel", "error", "-framerate", "10", "-start_number", "0", "-i", pattern,
               "-vf", "scale=trunc(iw/2)*2:trunc(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p",
               "-f", "mp4", mp4 + ".tmp"]
        if subprocess.run(cmd).returncode != 0:
            print(f"ryushi render: ffmpeg failed writing {mp4}", file=sys.stderr)
            sys.exit(1)
        os.replace(mp4 + ".tmp", mp4)
        print(f"{mp4} ({len(written)} frames)")


if __name__ == "__main__":
    main()
