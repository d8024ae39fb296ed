"""A state of a bushing run in ParaView: the deformed assembly (true scale)
cut at y = 0, coloured by a cell field (default the equivalent plastic
strain), without the rigid drop weight and support.

Usage:
    xvfb-run -a pvbatch doc/scripts/bushing_result_picture.py PVD PNG \
        [--time T] [--field equivalent_plastic_strain] [--title TEXT] \
        [--range LOW HIGH]

PVD is a run's solution.pvd; T (ms) picks the output nearest to it
(default the last). deal.II writes cell averages as point data (each
cell's own copies of its vertices), so the fields are read as POINTS. The
rigid parts are left out by their material ids
(10 support, 11 drop weight: parameter_files/meshes/bushing.geo). Needs
ParaView's Python (Debian: python3-paraview) and an X display (xvfb-run).
A documentation tool, not part of ctest; see doc/verification/bushing.md.
"""

import argparse

from paraview.simple import (Clip, ColorBy, GetActiveCamera,
                             GetActiveViewOrCreate, GetAnimationScene,
                             GetColorTransferFunction, GetScalarBar,
                             OpenDataFile, ResetCamera, SaveScreenshot, Show,
                             Text, Threshold, WarpByVector)

RIGID_MATERIAL_IDS = (10, 11)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("pvd")
    parser.add_argument("png")
    parser.add_argument("--time", type=float, default=None)
    parser.add_argument("--field", default="equivalent_plastic_strain")
    parser.add_argument("--title", default="")
    parser.add_argument("--range", type=float, nargs=2, default=None)
    args = parser.parse_args()

    reader = OpenDataFile(args.pvd)
    times = reader.TimestepValues
    if isinstance(times, (int, float)):
        times = [times]
    time = times[-1] if args.time is None else min(
        times, key=lambda t: abs(t - args.time))
    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.AnimationTime = time

    # The deformable parts only: material ids below the rigid ones.
    deformable = Threshold(Input=reader)
    deformable.Scalars = ["POINTS", "material_id"]
    deformable.LowerThreshold = 0
    deformable.UpperThreshold = min(RIGID_MATERIAL_IDS) - 0.5
    warp = WarpByVector(Input=deformable)
    warp.Vectors = ["POINTS", "displacement"]
    clip = Clip(Input=warp)
    clip.ClipType = "Plane"
    clip.ClipType.Origin = [0., 0., 0.]
    clip.ClipType.Normal = [0., -1., 0.]
    clip.Crinkleclip = 1

    view = GetActiveViewOrCreate("RenderView")
    view.ViewTime = time
    clip.UpdatePipeline(time)
    view.ViewSize = [1000, 900]
    view.UseColorPaletteForBackground = 0
    view.Background = [1., 1., 1.]
    view.OrientationAxesVisibility = 0
    display = Show(clip, view)
    display.SetRepresentationType("Surface With Edges")
    display.EdgeColor = [0.3, 0.3, 0.3]
    ColorBy(display, ("POINTS", args.field))
    lut = GetColorTransferFunction(args.field)
    if args.range:
        lut.RescaleTransferFunction(*args.range)
    else:
        display.RescaleTransferFunctionToDataRange(False, True)
    display.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(lut, view)
    bar.Title = args.field.replace("_", " ")
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0., 0., 0.]
    title = Text(Text=args.title or "t = %.3g ms" % time)
    title_display = Show(title, view)
    title_display.Color = [0., 0., 0.]
    title_display.FontSize = 14
    title_display.WindowLocation = "Upper Left Corner"

    camera = GetActiveCamera()
    camera.SetFocalPoint(0., 0., 25.)
    camera.SetPosition(0., -260., 60.)
    camera.SetViewUp(0., 0., 1.)
    ResetCamera()
    camera.Dolly(1.3)
    SaveScreenshot(args.png, view, ImageResolution=[1000, 900])


if __name__ == "__main__":
    main()
