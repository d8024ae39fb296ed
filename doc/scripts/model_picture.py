"""Render one time of a Model study's field output: the deformed parts, one
coloured by a field, the others in plain colours, so that the parts can be
told apart.

Usage:
    xvfb-run -a pvbatch doc/scripts/model_picture.py DIR --png FILE.png \
        [--time T] [--field NAME] [--coloured-part ID] [--title TEXT] \
        [--camera X,Y,Z] [--hide-others]

Opens DIR/solution.pvd (or DIR/solution.xdmf), goes to the time step nearest
to T ms (default: the last), warps the mesh by `displacement` (true scale)
and shows the cells of part_id ID (default 0) coloured by the scalar field
NAME (default von_mises_stress; stresses converted from GPa to MPa) and
every other part in grey, with the mesh edges. The title (default: the
directory and the time; a literal "\\n" starts a new line) is written in
the top left corner. Needs ParaView's Python (Debian: python3-paraview) and
an X display (xvfb-run). A documentation tool, not part of ctest; see
doc/model.md for the figure it made.
"""

import argparse
import os
import sys

from paraview.simple import (Calculator, ColorBy, Delete, GetActiveCamera,
                             GetActiveViewOrCreate, GetColorTransferFunction,
                             GetScalarBar, OpenDataFile, ResetCamera,
                             SaveScreenshot, Show, Text, Threshold,
                             WarpByVector)

# Units of the fields rubberdyn writes (postprocess::FieldOutput).
UNITS = {"von_mises_stress": "GPa", "pressure": "GPa", "J": "-",
         "cauchy_stress_zz": "GPa", "displacement": "mm",
         "contact_pressure": "GPa", "contact_gap": "mm", "contact_slip": "mm"}


def time_steps(reader):
    """The time values of a reader as a list."""
    values = reader.TimestepValues
    if values is None:
        return []
    if isinstance(values, (int, float)):
        return [values]
    return list(values)


def association(reader, name):
    """Where @p reader has the array @p name: "CELLS" or "POINTS" (deal.II's
    DataOut writes cell data as constant point data of unshared points)."""
    return "CELLS" if name in reader.CellData.keys() else "POINTS"


def part(source, where, part_id, inside):
    """The cells of @p source with part_id == @p part_id (inside) or !=."""
    threshold = Threshold(Input=source)
    threshold.Scalars = [where, "part_id"]
    threshold.LowerThreshold = part_id - 0.5
    threshold.UpperThreshold = part_id + 0.5
    threshold.ThresholdMethod = "Between"
    threshold.Invert = 0 if inside else 1
    return threshold


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("directory", metavar="DIR")
    parser.add_argument("--png", required=True)
    parser.add_argument("--time", type=float)
    parser.add_argument("--field", default="von_mises_stress")
    parser.add_argument("--coloured-part", type=int, default=0)
    parser.add_argument("--title")
    parser.add_argument("--camera", default="55,-45,30")
    parser.add_argument("--hide-others", action="store_true")
    args = parser.parse_args()

    index = None
    for name in ("solution.pvd", "solution.xdmf"):
        if os.path.exists(os.path.join(args.directory, name)):
            index = os.path.join(args.directory, name)
            break
    if index is None:
        print("%s: neither solution.pvd nor solution.xdmf" % args.directory)
        return 1
    reader = OpenDataFile(index)
    reader.UpdatePipelineInformation()
    times = time_steps(reader)
    time = times[-1] if args.time is None else \
        min(times, key=lambda t: abs(t - args.time))

    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [1000, 800]
    view.ViewTime = time
    view.OrientationAxesVisibility = 1
    view.Background = [1., 1., 1.]
    try:  # ParaView >= 5.10 has a palette that overrides Background
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    warp = WarpByVector(Input=reader)
    warp.Vectors = ["POINTS", "displacement"]

    # Stresses in MPa: the GPa of the output give labels like 0.00023.
    where = association(reader, args.field)
    field, unit = args.field, UNITS.get(args.field, "?")
    source = warp
    if unit == "GPa":
        field, unit = args.field + "_MPa", "MPa"
        source = Calculator(Input=warp)
        source.AttributeType = "Cell Data" if where == "CELLS" else \
            "Point Data"
        source.ResultArrayName = field
        source.Function = "1000 * " + args.field

    coloured = Show(part(source, association(reader, "part_id"),
                         args.coloured_part, True), view)
    coloured.SetRepresentationType("Surface With Edges")
    coloured.EdgeColor = [0.15, 0.15, 0.15]
    coloured.Ambient = 0.3  # faces turned from the light stay readable
    ColorBy(coloured, (where, field))
    coloured.RescaleTransferFunctionToDataRange(False, True)
    coloured.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(GetColorTransferFunction(field), view)
    bar.Title = "%s (%s)" % (args.field.replace("_", " "), unit)
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0., 0., 0.]
    bar.RangeLabelFormat = "%-#6.2g"

    if not args.hide_others:
        others = Show(part(warp, association(reader, "part_id"),
                           args.coloured_part, False), view)
        others.SetRepresentationType("Surface With Edges")
        others.ColorArrayName = ["POINTS", ""]
        others.AmbientColor = others.DiffuseColor = [0.72, 0.74, 0.78]
        others.EdgeColor = [0.15, 0.15, 0.15]

    # "\n" in --title starts a new line.
    title = Text(Text=args.title.replace("\\n", "\n") if args.title else
                 "%s, t = %.3g ms" % (args.directory, time))
    title_display = Show(title, view)
    title_display.WindowLocation = "Upper Left Corner"
    title_display.FontSize = 13
    title_display.Justification = "Left"
    title_display.Color = [0., 0., 0.]

    camera = GetActiveCamera()
    camera.SetFocalPoint(10., 10., 5.)
    camera.SetPosition(*[float(c) for c in args.camera.split(",")])
    camera.SetViewUp(0., 0., 1.)
    ResetCamera()
    camera.Zoom(1.2)
    SaveScreenshot(args.png, view, ImageResolution=[1000, 800],
                   CompressionLevel="9")
    print("wrote %s (t = %.6g ms)" % (args.png, time))
    # As in check_paraview.py: avoids GLXBadContext at exit under Xvfb.
    Delete(view)
    return 0


if __name__ == "__main__":
    sys.exit(main())
