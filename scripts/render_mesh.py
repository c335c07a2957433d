"""Renders a refined mesh coloured by ColorId, cut open so that the interior shows.

When the mesh has a Material array with an isolation oxide (id 8, as written by
`cgmesh generate finfet`), that surrounding oxide is left out so that the device shows.

Usage: pvbatch render_mesh.py IN.vtu OUT.png   (under xvfb-run: rendering needs an X server)
"""
import sys

from paraview.simple import (Clip, ColorBy, GetActiveViewOrCreate, GetColorTransferFunction,
                             Render, ResetCamera, SaveScreenshot, Show, Threshold,
                             XMLUnstructuredGridReader)

ISOLATION_OXIDE = 8


def render(input_file, image_file):
    reader = XMLUnstructuredGridReader(FileName=[input_file])
    reader.UpdatePipeline()
    bounds = reader.GetDataInformation().GetBounds()
    center = [(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2,
              (bounds[4] + bounds[5]) / 2]

    source = reader
    material = reader.CellData.GetArray("Material")
    if material is not None and material.GetRange()[1] >= ISOLATION_OXIDE:
        source = Threshold(Input=reader, Scalars=["CELLS", "Material"],
                           LowerThreshold=0, UpperThreshold=ISOLATION_OXIDE - 1)

    # Cut along a plane through the centre (y below it): the cut face shows the colours inside.
    # Not a crinkle clip: whole cells from both sides of a partition boundary that runs along the
    # plane (Hilbert parts are cut along grid planes) would speckle the face.
    clip = Clip(Input=source)
    clip.ClipType = "Plane"
    clip.ClipType.Origin = center
    clip.ClipType.Normal = [0.0, 1.0, 0.0]
    clip.Crinkleclip = 0

    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [1280, 1024]
    view.OrientationAxesVisibility = 1
    display = Show(clip, view)
    display.SetRepresentationType("Surface With Edges")
    display.EdgeColor = [0.15, 0.15, 0.15]
    ColorBy(display, ("CELLS", "ColorId"))
    colors = GetColorTransferFunction("ColorId")
    colors.ApplyPreset("Rainbow Uniform", True)
    display.SetScalarBarVisibility(view, True)

    # Look at the cut face (it faces +y) from above and in front.
    view.CameraPosition = [center[0] + 0.8 * (bounds[1] - bounds[0]) + 1e-9,
                           center[1] + 2.0 * (bounds[3] - bounds[2]) + 1e-9,
                           center[2] + 0.9 * (bounds[5] - bounds[4]) + 1e-9]
    view.CameraFocalPoint = center
    view.CameraViewUp = [0.0, 0.0, 1.0]
    ResetCamera(view)
    Render(view)
    SaveScreenshot(image_file, view, ImageResolution=[1280, 1024])


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: pvbatch render_mesh.py IN.vtu OUT.png")
    render(sys.argv[1], sys.argv[2])
