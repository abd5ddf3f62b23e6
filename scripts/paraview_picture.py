"""A curved (P2) .vtu of hocav as ParaView sees it: what it reads and a picture of the curved cells.

Run by ParaView's Python (needs a display; headless, under Xvfb: `xvfb-run -a pvbatch ...`):

    pvbatch scripts/paraview_picture.py MESH.vtu PICTURE.png [--radii R_IN,R_OUT] [--subdivision N]

Prints one JSON line: the cell types and their counts (VTK codes: 22 quadratic triangle, 24
quadratic tetrahedron), the number of points, and with --radii (3D: a shell between two spheres
centred at the origin) the median distance of its boundary to them as ParaView draws it:
straight, from the cells' corners only (over the midpoints of the boundary edges), and curved, with
the nonlinear subdivision of N levels (over the points of the subdivided boundary). Curved cells
read as curved when the second is much smaller than the first. (Medians: a few boundary vertices
of an adapted mesh may lie off the true shell, where the P3 surrogate was off it.)

The picture: the mesh cut by the plane z = 0 (whole cells, on the side z < 0, 3D) or the whole mesh
(2D), drawn with N levels of nonlinear subdivision (default 3) so that curved edges and faces show,
coloured by the cells' min normalized Jacobian.
"""
import argparse
import collections
import json
import math

from paraview import servermanager
from paraview.simple import (ColorBy, CreateView, ExtractSurface, GetColorTransferFunction, GetScalarBar, Clip,
                             Render, SaveScreenshot, Show, XMLUnstructuredGridReader)

QUADRATIC_TETRA = 24


def arguments():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mesh")
    parser.add_argument("picture")
    parser.add_argument("--radii", help="R_IN,R_OUT of a 3D shell centred at the origin")
    parser.add_argument("--subdivision", type=int, default=3)
    return parser.parse_args()


def cell_types(data):
    return collections.Counter(data.GetCellType(i) for i in range(data.GetNumberOfCells()))


def distance_to_shell(point, radii):
    radius = math.sqrt(sum(x * x for x in point))
    return min(abs(radius - r) for r in radii)


def boundary_surface(reader, subdivision):
    surface = ExtractSurface(Input=reader)
    surface.NonlinearSubdivisionLevel = subdivision
    surface.UpdatePipeline()
    return servermanager.Fetch(surface)


def median(values):
    return sorted(values)[len(values) // 2]


def straight_boundary_deviation(reader, radii):
    """The boundary drawn from the corners only (level 0): distances of its edges' midpoints."""
    surface = boundary_surface(reader, 0)
    distances = []
    for cell in range(surface.GetNumberOfCells()):
        ids = surface.GetCell(cell).GetPointIds()
        corners = [surface.GetPoint(ids.GetId(k)) for k in range(ids.GetNumberOfIds())]
        for a, b in zip(corners, corners[1:] + corners[:1]):
            distances.append(distance_to_shell([(x + y) / 2 for x, y in zip(a, b)], radii))
    return median(distances)


def curved_boundary_deviation(reader, radii, subdivision):
    surface = boundary_surface(reader, subdivision)
    return median([distance_to_shell(surface.GetPoint(i), radii) for i in range(surface.GetNumberOfPoints())])


def draw(reader, dimension, subdivision, picture):
    shown = reader
    if dimension == 3:
        shown = Clip(Input=reader)
        shown.ClipType = "Plane"
        shown.ClipType.Origin = [0, 0, 0]
        shown.ClipType.Normal = [0, 0, 1]
        shown.Crinkleclip = 1  # whole cells, still quadratic
    view = CreateView("RenderView")
    view.ViewSize = [1200, 900]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [1, 1, 1]
    display = Show(shown, view)
    display.SetRepresentationType("Surface With Edges")
    display.EdgeColor = [0.1, 0.1, 0.1]
    display.NonlinearSubdivisionLevel = subdivision
    ColorBy(display, ("CELLS", "min_normalized_jacobian"))
    colors = GetColorTransferFunction("min_normalized_jacobian")
    colors.ApplyPreset("Viridis (matplotlib)", True)
    colors.RescaleTransferFunction(0.0, 1.0)
    bar = GetScalarBar(colors, view)
    bar.Title = "min normalized Jacobian"
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    bar.TitleFontSize = bar.LabelFontSize = 12
    bar.RangeLabelFormat = "%.1f"
    bar.Visibility = 1
    Render(view)  # fits the camera to the data; then look at the cut from above, slanted
    if dimension == 3:
        camera = view.GetActiveCamera()
        camera.SetFocalPoint(0.35, 0.0, -0.2)
        camera.SetPosition(0.9, -1.5, 1.6)
        camera.SetViewUp(0, 0, 1)
        camera.SetViewAngle(30)
    SaveScreenshot(picture, view, ImageResolution=[1000, 750], CompressionLevel="9")


def main():
    options = arguments()
    reader = XMLUnstructuredGridReader(FileName=[options.mesh])
    reader.UpdatePipeline()
    data = servermanager.Fetch(reader)
    types = cell_types(data)
    dimension = 3 if QUADRATIC_TETRA in types else 2
    facts = {"cell_types": {str(code): count for code, count in sorted(types.items())},
             "points": data.GetNumberOfPoints()}
    if options.radii:
        if dimension != 3:
            raise SystemExit("--radii: the boundary distances are for 3D shells")
        radii = [float(r) for r in options.radii.split(",")]
        facts["straight_boundary_median_distance"] = straight_boundary_deviation(reader, radii)
        facts["curved_boundary_median_distance"] = curved_boundary_deviation(reader, radii, options.subdivision)
    draw(reader, dimension, options.subdivision, options.picture)
    print(json.dumps(facts))


main()
