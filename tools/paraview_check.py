"""Opens a ryushi run's particles.xdmf in ParaView's own readers and checks what a user sees.

Run with ParaView's interpreter under a virtual display (rendering needs an X server here):

    xvfb-run -a pvpython tools/paraview_check.py OUT --expect-points N --expect-times T0,T1,...
        [--arrays a,b,c] [--image-dir DIR] [--label NAME] [--color FIELD] [--z-equals FIELD]

For each reader ParaView offers for XDMF (the legacy XDMFReader, Xdmf3ReaderS and
Xdmf3ReaderT), and for OpenDataFile (what File > Open picks), it asserts
  - the point count and a cell per particle (a reader that builds no cells draws nothing),
  - the point-data arrays and their component counts (vectors 3, tensors 9),
  - the time values, as written,
  - a rendered image that is not empty (pixels differ from the background),
and saves the image as DIR/NAME_READER.png. With --z-equals FIELD it also asserts that the
points' z coordinate is that point array (a shallow-water run draws its particles on the water
surface, z = surface_elevation). Prints one line per reader and exits 1 on the
first failure, naming the reader and what it saw.
"""
import argparse
import os
import sys

from paraview import simple as pv  # noqa: E402  (ParaView's own module)

READERS = ["XDMFReader", "Xdmf3ReaderS", "Xdmf3ReaderT", "OpenDataFile"]
VECTORS = {"position": 3, "velocity": 3, "acceleration": 3, "surface_normal": 3, "displacement": 3,
           "tension_normal": 3}


def fail(reader, what):
    print(f"paraview_check: {reader}: {what}", file=sys.stderr)
    sys.exit(1)


def open_with(reader, path):
    if reader == "OpenDataFile":
        return pv.OpenDataFile(path)
    if reader == "XDMFReader":
        return pv.XDMFReader(FileNames=[path])
    return getattr(pv, reader)(FileName=[path])


def background_differs(png):
    """True when the image holds pixels other than its corner (background) colour."""
    from vtkmodules.vtkIOImage import vtkPNGReader

    r = vtkPNGReader()
    r.SetFileName(png)
    r.Update()
    img = r.GetOutput()
    scalars = img.GetPointData().GetScalars()
    comps = scalars.GetNumberOfComponents()
    corner = [scalars.GetComponent(0, c) for c in range(comps)]
    differ = 0
    for i in range(0, scalars.GetNumberOfTuples(), 7):
        if any(abs(scalars.GetComponent(i, c) - corner[c]) > 8 for c in range(comps)):
            differ += 1
    return differ


def check_z(reader, src, field):
    """The points' z equals the point array `field` at the pipeline's time, and is not all zero."""
    import numpy as np
    from paraview import servermanager as sm
    from vtkmodules.numpy_interface import dataset_adapter as dsa

    data = dsa.WrapDataObject(sm.Fetch(src))
    points, values = data.Points, data.PointData[field]
    if hasattr(points, "Arrays"):  # a composite data set (one block per grid)
        points = np.concatenate([np.asarray(p) for p in points.Arrays])
        values = np.concatenate([np.asarray(v) for v in values.Arrays])
    points, values = np.asarray(points), np.asarray(values)
    gap = float(np.max(np.abs(points[:, 2] - values)))
    if gap > 1e-12 or not np.any(values != 0):
        fail(reader, f"point z differs from '{field}' by up to {gap} (or '{field}' is all zero)")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--expect-points", type=int, required=True)
    ap.add_argument("--expect-times", required=True)
    ap.add_argument("--arrays", default="velocity,pressure,density,kind,id")
    ap.add_argument("--tensors", default="")
    ap.add_argument("--image-dir", default="")
    ap.add_argument("--label", default="run")
    ap.add_argument("--color", default="pressure")
    ap.add_argument("--z-equals", default="")
    a = ap.parse_args()

    path = os.path.join(a.out, "particles.xdmf")
    times = [float(t) for t in a.expect_times.split(",")]
    tensors = [t for t in a.tensors.split(",") if t]
    for reader in READERS:
        src = open_with(reader, path)
        if src is None:
            fail(reader, "ParaView opened nothing")
        # One time step comes back as a bare number (0.0 for an initial frame, which is falsy).
        values = src.TimestepValues
        got_times = [] if values is None else list(values) if hasattr(values, "__len__") else [float(values)]
        if len(got_times) != len(times) or any(abs(g - t) > 1e-9 * max(1, abs(t)) for g, t in zip(got_times, times)):
            fail(reader, f"time values {got_times}, expected {times}")
        src.UpdatePipeline(times[-1])
        info = src.GetDataInformation()
        points, cells = info.GetNumberOfPoints(), info.GetNumberOfCells()
        if points != a.expect_points:
            fail(reader, f"{points} points, expected {a.expect_points}")
        if cells != points:
            fail(reader, f"{cells} cells for {points} points (a particle needs a vertex cell to be drawn)")
        pdi = src.PointData
        for name in [n for n in a.arrays.split(",") if n] + tensors:
            if name not in pdi.keys():
                fail(reader, f"no point array '{name}' (has {list(pdi.keys())})")
            want = 9 if name in tensors else VECTORS.get(name, 1)
            got = pdi[name].GetNumberOfComponents()
            if got != want:
                fail(reader, f"array '{name}' has {got} components, expected {want}")
        if a.z_equals:
            check_z(reader, src, a.z_equals)
        view = pv.CreateRenderView()
        view.ViewSize = [640, 400]
        view.ViewTime = times[-1]
        view.OrientationAxesVisibility = 0
        display = pv.Show(src, view)
        pv.ColorBy(display, ("POINTS", a.color))
        display.RescaleTransferFunctionToDataRange(True, False)
        display.SetScalarBarVisibility(view, True)
        bounds = info.GetBounds()
        if bounds[5] > bounds[4]:  # 3D: look at the tank from the front, slightly above
            centre = [0.5 * (bounds[2 * k] + bounds[2 * k + 1]) for k in range(3)]
            size = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
            view.CameraFocalPoint = centre
            view.CameraPosition = [centre[0] + 0.6 * size, centre[1] - 2.0 * size, centre[2] + 1.0 * size]
            view.CameraViewUp = [0, 0, 1]
        view.ResetCamera()
        if a.image_dir:
            os.makedirs(a.image_dir, exist_ok=True)
            png = os.path.join(a.image_dir, f"{a.label}_{reader}.png")
        else:
            png = os.path.join(a.out, f"paraview_{reader}.png")
        pv.SaveScreenshot(png, view, ImageResolution=[640, 400])
        lit = background_differs(png)
        if lit < 50:
            fail(reader, f"the rendered image {png} is empty ({lit} sampled pixels differ from the background)")
        print(f"paraview_check: {a.label} {reader}: {points} points, {cells} cells, "
              f"{len(got_times)} times, {lit} lit samples -> {png}")
        pv.Delete(display)
        pv.Delete(view)
        pv.Delete(src)
    print("paraview_check: all readers draw the particles")


if __name__ == "__main__":
    main()
