"""Open rubberdyn field output in ParaView and print what ParaView sees.

Usage:
    pvpython doc/scripts/check_paraview.py DIR [DIR ...]
    xvfb-run -a pvbatch doc/scripts/check_paraview.py DIR --png FILE.png

For every DIR, opens DIR/solution.pvd (Field output format = vtu) and/or
DIR/solution.xdmf (Field output format = hdf5), whichever exist, goes to the
last time step and prints the number of time steps, the last time, the point
and cell counts, and every point and cell array with its number of
components and its range (the magnitude range for vectors, then the range
of each component). It fails (exit status 1) if an index is missing or one
of the fields the drop test writes is absent. With several indices (e.g.
the same input run in both formats, on 1 and 2 ranks), it also checks that
they have the same time steps and the same field ranges at the last time.

With --png, renders the last time step (or, with --time T, the one nearest
to T ms) of the first index found, warped by the displacement and coloured
by the von Mises stress, into FILE.png (needs an X display: run it with
xvfb-run -a pvbatch).

A developer tool, not part of ctest: ParaView is a heavy dependency
(Debian: apt-get install python3-paraview; xvfb for --png).
"""

import argparse
import os
import sys

from paraview.simple import (ColorBy, Delete, GetActiveCamera,
                             GetActiveViewOrCreate, GetColorTransferFunction,
                             GetScalarBar, OpenDataFile, ResetCamera,
                             SaveScreenshot, Show, WarpByVector)

# What rubberdyn's drop test writes (postprocess::FieldOutput).
EXPECTED = ["displacement", "velocity",
            "cauchy_stress_xx", "cauchy_stress_yy", "cauchy_stress_zz",
            "cauchy_stress_xy", "cauchy_stress_xz", "cauchy_stress_yz",
            "von_mises_stress", "pressure", "J", "equivalent_plastic_strain",
            "mpi_rank"]


def time_steps(reader):
    """The time values of a reader as a list (ParaView gives a float when
    there is only one)."""
    values = reader.TimestepValues
    if values is None:
        return []
    if isinstance(values, (int, float)):
        return [values]
    return list(values)


def print_arrays(kind, arrays, ranges):
    """Print each array; record its component ranges in @p ranges."""
    for name in arrays.keys():
        array = arrays[name]
        n = array.GetNumberOfComponents()
        line = "    %-6s %-18s %d component%s" % (kind, name, n,
                                                   "s" if n > 1 else " ")
        if n > 1:
            line += ", |.| in [%.6g, %.6g]; " % tuple(array.GetRange(-1))
            line += ", ".join("[%.6g, %.6g]" % tuple(array.GetRange(c))
                              for c in range(n))
        else:
            line += ", in [%.6g, %.6g]" % tuple(array.GetRange(0))
        print(line)
        ranges[name] = [tuple(array.GetRange(c)) for c in range(n)]


def check(path):
    """Print what ParaView reads from one index file; return the reader,
    (number of time steps, last time), the component ranges of every array
    and the list of missing fields."""
    reader = OpenDataFile(path)
    if reader is None:
        print("%s: ParaView found no reader" % path)
        return None, None, {}, EXPECTED
    reader.UpdatePipelineInformation()
    times = time_steps(reader)
    last = times[-1] if times else 0.
    reader.UpdatePipeline(last)
    info = reader.GetDataInformation()
    print("%s (%s)" % (path, reader.GetXMLName()))
    print("  %d time steps, last t = %.6g ms: %d points, %d cells" %
          (len(times), last, info.GetNumberOfPoints(),
           info.GetNumberOfCells()))
    ranges = {}
    print_arrays("point", reader.PointData, ranges)
    print_arrays("cell", reader.CellData, ranges)
    missing = [name for name in EXPECTED if name not in ranges]
    if missing:
        print("  MISSING: " + ", ".join(missing))
    return reader, (len(times), last), ranges, missing


def compare(results):
    """Compare the last-step ranges of every index with those of the first.

    Runs of the same input in either format and on any number of ranks
    must show the same fields: deal.II's vtu files store floats, so ranges
    agree to float precision (relative 1e-6 of the largest magnitude of
    the field), except mpi_rank, which depends on the number of ranks.
    Returns the number of disagreements."""
    reference_path, reference = results[0]
    n_bad = 0
    for path, result in results[1:]:
        bad = []
        if result["time"][0] != reference["time"][0] or \
           abs(result["time"][1] - reference["time"][1]) > \
           1e-9 * abs(reference["time"][1]):
            bad.append("time steps %s != %s" % (result["time"],
                                                  reference["time"]))
        for name in EXPECTED:
            if name == "mpi_rank" or name not in result["ranges"] or \
               name not in reference["ranges"]:
                continue
            a, b = reference["ranges"][name], result["ranges"][name]
            scale = max(abs(v) for pair in a for v in pair) or 1.
            if len(a) != len(b) or any(
                    abs(x - y) > 1e-6 * scale
                    for pa, pb in zip(a, b) for x, y in zip(pa, pb)):
                bad.append(name)
        if bad:
            print("%s differs from %s: %s" % (path, reference_path,
                                               ", ".join(bad)))
        else:
            print("%s agrees with %s (last time, all field ranges)" %
                  (path, reference_path))
        n_bad += len(bad)
    return n_bad


def render(reader, time, png):
    """The deformed body at @p time, coloured by von Mises stress."""
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [900, 900]
    view.ViewTime = time
    view.OrientationAxesVisibility = 0
    warp = WarpByVector(Input=reader)
    warp.Vectors = ["POINTS", "displacement"]
    display = Show(warp, view)
    association = ("CELLS" if "von_mises_stress" in reader.CellData.keys()
                   else "POINTS")
    ColorBy(display, (association, "von_mises_stress"))
    display.SetScalarBarVisibility(view, True)
    display.RescaleTransferFunctionToDataRange(False, True)
    bar = GetScalarBar(GetColorTransferFunction("von_mises_stress"), view)
    bar.Title = "von Mises stress (GPa)"
    bar.ComponentTitle = ""
    display.EdgeColor = [0.2, 0.2, 0.2]
    display.SetRepresentationType("Surface With Edges")
    camera = GetActiveCamera()
    camera.SetPosition(70., -90., 30.)
    camera.SetFocalPoint(0., 0., 5.)
    camera.SetViewUp(0., 0., 1.)
    ResetCamera()
    SaveScreenshot(png, view, ImageResolution=[900, 900])
    print("wrote %s (t = %.6g ms)" % (png, time))
    # Without this, ParaView 5.11 under Xvfb fails with GLXBadContext (exit
    # status 1) while tearing the render window down at exit.
    Delete(view)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("directories", nargs="+", metavar="DIR")
    parser.add_argument("--png", help="render the first index to this PNG")
    parser.add_argument("--time", type=float,
                        help="render the time step nearest to this time (ms) "
                             "instead of the last one")
    args = parser.parse_args()

    failed = False
    first = None
    results = []
    for directory in args.directories:
        found = False
        for index in ("solution.pvd", "solution.xdmf"):
            path = os.path.join(directory, index)
            if not os.path.exists(path):
                continue
            found = True
            reader, time, ranges, missing = check(path)
            failed = failed or reader is None or bool(missing)
            if reader is None:
                continue
            results.append((path, {"time": time, "ranges": ranges}))
            if first is None:
                first = reader
        if not found:
            print("%s: neither solution.pvd nor solution.xdmf" % directory)
            failed = True
    if len(results) > 1 and compare(results) > 0:
        failed = True
    if args.png and first is not None:
        times = time_steps(first)
        time = times[-1] if args.time is None else \
            min(times, key=lambda t: abs(t - args.time))
        render(first, time, args.png)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
