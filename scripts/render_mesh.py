"""Renders a refined mesh coloured by ColorId, clipped so that the interior cells show.

Usage: pvbatch render_mesh.py IN.vtu OUT.png   (under xvfb-run: rendering needs an X server)
"""
import sys

from paraview.simple import (Clip, ColorBy, GetActiveViewOrCreate, GetColorTransferFunction,
                             Render, ResetCamera, SaveScreenshot, Show, XMLUnstructuredGridReader)


def render(input_file, image_file):
    reader = XMLUnstructuredGridReader(FileName=[input_file])
    reader.UpdatePipeline()
    bounds = reader.GetDataInformation().GetBounds()
    center = [(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2,
              (bounds[4] + bounds[5]) / 2]

    # Keep whole cells on one side of a plane through the centre: the cut shows inner cells.
    clip = Clip(Input=reader)
    clip.ClipType = "Plane"
    clip.ClipType.Origin = center
    clip.ClipType.Normal = [1.0, 0.0, 0.0]
    clip.Crinkleclip = 1

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

    view.CameraPosition = [center[0] + 2.0 * (bounds[1] - bounds[0]) + 1e-9,
                           center[1] - 1.5 * (bounds[3] - bounds[2]) - 1e-9,
                           center[2] + 1.2 * (bounds[5] - bounds[4]) + 1e-9]
    view.CameraFocalPoint = center
    view.CameraViewUp = [0.0, 0.0, 1.0]
    ResetCamera(view)
    Render(view)
    SaveScreenshot(image_file, view, ImageResolution=[1280, 1024])


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: pvbatch render_mesh.py IN.vtu OUT.png")
    render(sys.argv[1], sys.argv[2])
