"""Render the bushing assembly's mesh coloured by material id, cut in half
at y = 0 to show the inside: doc/figures/bushing_assembly.png (the whole
assembly, from the cut side and above) and doc/figures/bushing_section.png
(the bushing's section, seen along +y in parallel projection).

Usage:
    xvfb-run -a pvbatch doc/scripts/bushing_screenshot.py \
        [--mesh parameter_files/meshes/bushing.msh] \
        [--png doc/figures/bushing_assembly.png] \
        [--section-png doc/figures/bushing_section.png]

Reads the Gmsh mesh (ASCII format 2.2, hexahedra with their physical volume
tag, as parameter_files/meshes/regenerate.sh writes it) into a VTK
unstructured grid with a cell array material_id, keeps the half y >= 0
(a clip at the plane y = 0, which cuts through cells: the cut faces are
flat) and shows it from the cut side, -y, with the mesh edges. Needs
ParaView's Python (Debian: python3-paraview) and an X display (xvfb-run).
A documentation tool, not part of ctest; see doc/bushing.md.
"""

import argparse
import os
import sys
import tempfile

from paraview.simple import (Clip, ColorBy, Delete, GetActiveCamera,
                             GetActiveViewOrCreate, GetColorTransferFunction,
                             GetScalarBar, OpenDataFile, ResetCamera,
                             SaveScreenshot, Show, Text)
from vtkmodules.vtkCommonCore import vtkIntArray, vtkPoints
from vtkmodules.vtkCommonDataModel import VTK_HEXAHEDRON, vtkUnstructuredGrid
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter

# Material ids of parameter_files/meshes/bushing.geo.
PARTS = ["bolt", "nut", "washer", "inner sleeve", "rubber",
         "plastic outer sleeve", "metal outer sleeve", "plate", "brace",
         "support", "drop weight"]

# One colour per part (RGB in [0, 1]): metals in greys and blues, the
# rubber dark, the plastic sleeve light, rigid bodies pale.
COLOURS = [(0.35, 0.38, 0.45), (0.55, 0.45, 0.35), (0.70, 0.72, 0.75),
           (0.78, 0.80, 0.86), (0.15, 0.15, 0.15), (0.95, 0.85, 0.45),
           (0.45, 0.55, 0.75), (0.40, 0.65, 0.45), (0.75, 0.45, 0.40),
           (0.85, 0.85, 0.80), (0.85, 0.80, 0.90)]


def read_msh22(path):
    """The hexahedra of a Gmsh 2.2 ASCII file as a vtkUnstructuredGrid with
    the cell array material_id (the physical tag)."""
    with open(path) as stream:
        lines = stream.read().split("\n")
    start = lines.index("$Nodes")
    n_nodes = int(lines[start + 1])
    points = vtkPoints()
    index = {}
    for k, line in enumerate(lines[start + 2:start + 2 + n_nodes]):
        fields = line.split()
        index[int(fields[0])] = k
        points.InsertNextPoint(*map(float, fields[1:4]))
    start = lines.index("$Elements")
    n_elements = int(lines[start + 1])
    grid = vtkUnstructuredGrid()
    grid.SetPoints(points)
    material = vtkIntArray()
    material.SetName("material_id")
    for line in lines[start + 2:start + 2 + n_elements]:
        fields = [int(f) for f in line.split()]
        if fields[1] != 5:  # hexahedra only
            continue
        # Gmsh's and VTK's hexahedra number their vertices alike.
        grid.InsertNextCell(VTK_HEXAHEDRON, 8,
                            [index[v] for v in fields[-8:]])
        material.InsertNextValue(fields[3])
    grid.GetCellData().AddArray(material)
    return grid


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--mesh", default="parameter_files/meshes/bushing.msh")
    parser.add_argument("--png", default="doc/figures/bushing_assembly.png")
    parser.add_argument("--section-png",
                        default="doc/figures/bushing_section.png")
    args = parser.parse_args()

    grid = read_msh22(args.mesh)
    vtu = os.path.join(tempfile.mkdtemp(), "bushing.vtu")
    writer = vtkXMLUnstructuredGridWriter()
    writer.SetFileName(vtu)
    writer.SetInputData(grid)
    writer.Write()
    reader = OpenDataFile(vtu)

    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [1600, 1000]
    view.OrientationAxesVisibility = 1
    view.Background = [1., 1., 1.]
    try:  # ParaView >= 5.10 has a palette that overrides Background
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass

    # Keep y >= 0: the clip removes the side the plane's normal points to
    # unless inverted (ParaView's default Invert = 1 keeps the other side).
    clip = Clip(Input=reader)
    clip.ClipType = "Plane"
    clip.ClipType.Origin = [0., 0., 0.]
    clip.ClipType.Normal = [0., 1., 0.]
    clip.Invert = 0
    display = Show(clip, view)
    display.SetRepresentationType("Surface With Edges")
    display.EdgeColor = [0.1, 0.1, 0.1]
    display.Ambient = 0.25
    ColorBy(display, ("CELLS", "material_id"))
    lut = GetColorTransferFunction("material_id")
    lut.InterpretValuesAsCategories = 1
    annotations, colours = [], []
    for part_id, (name, colour) in enumerate(zip(PARTS, COLOURS), 1):
        annotations += [str(part_id), "%d %s" % (part_id, name)]
        colours += list(colour)
    lut.Annotations = annotations
    lut.IndexedColors = colours
    display.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(lut, view)
    bar.Title = "material id"
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0., 0., 0.]
    bar.WindowLocation = "Any Location"
    bar.Position = [0.87, 0.6]

    title = Text(Text="bushing.msh: the assembly cut at y = 0 "
                 "(%d cells)" % grid.GetNumberOfCells())
    title_display = Show(title, view)
    title_display.WindowLocation = "Upper Left Corner"
    title_display.FontSize = 14
    title_display.Color = [0., 0., 0.]

    # From the cut side (-y), a little from above and from +x's side.
    camera = GetActiveCamera()
    camera.SetFocalPoint(60., 0., 20.)
    camera.SetPosition(-120., -520., 220.)
    camera.SetViewUp(0., 0., 1.)
    ResetCamera()
    camera.Zoom(1.35)
    SaveScreenshot(args.png, view, ImageResolution=[1600, 1000],
                   CompressionLevel="9")
    print("wrote %s" % args.png)

    # The bushing's section: the cut face y = 0 seen along +y, z from about
    # -30 to 80 (parallel projection: true proportions).
    title.Text = "bushing.msh: the section y = 0 (z up, x to the right)"
    view.CameraParallelProjection = 1
    camera.SetFocalPoint(12., 0., 25.)
    camera.SetPosition(12., -500., 25.)
    camera.SetViewUp(0., 0., 1.)
    camera.SetParallelScale(56.)
    SaveScreenshot(args.section_png, view, ImageResolution=[1600, 1000],
                   CompressionLevel="9")
    print("wrote %s" % args.section_png)
    Delete(view)  # avoids GLXBadContext at exit under Xvfb
    return 0


if __name__ == "__main__":
    sys.exit(main())
