"""Refine a tetrahedral mesh with the CoarseGrainedMesher plugin, colour it by ColorId and save a
screenshot: the paraview.simple way.

    xvfb-run -a -s '-screen 0 1280x1024x24' pvbatch examples/refine_and_render.py \
        Data/finfet-small.vtu finfet-colors.png --region-array Material

(xvfb-run only on a machine without a display: ParaView's VTK renders through X.) --plugin
defaults to the plugin in this checkout's build/ directory; pass the installed
lib/paraview-5.11/plugins/CoarseGrainedMesher/CoarseGrainedMesher.so otherwise.
"""
import argparse
import os

from paraview.simple import (Clip, ColorBy, CreateView, GetColorTransferFunction, LoadPlugin,
                             OpenDataFile, Render, ResetCamera, SaveData, SaveScreenshot, Show)

REPOSITORY = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD_TREE_PLUGIN = os.path.join(REPOSITORY, "build", "lib", "paraview-5.11", "plugins",
                                 "CoarseGrainedMesher", "CoarseGrainedMesher.so")


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("input", help="tetrahedral mesh (.vtu, .vtk, anything ParaView reads)")
    parser.add_argument("screenshot", help="PNG to write")
    parser.add_argument("--plugin", default=BUILD_TREE_PLUGIN, help="CoarseGrainedMesher.so")
    parser.add_argument("--region-array", default="None", help="cell array of material ids")
    parser.add_argument("--partitions", type=int, default=64)
    parser.add_argument("--edge-length-factor", type=float, default=0.5)
    parser.add_argument("--output", help="also save the refined mesh (.vtu)")
    # pvbatch passes its own options through to the script: ignore those.
    options, _ = parser.parse_known_args()
    return options


def main():
    options = parse_arguments()
    # ns=globals() makes the plugin's filter a paraview.simple function of this module.
    LoadPlugin(options.plugin, ns=globals())

    mesh = OpenDataFile(options.input)
    refined = CoarseGrainedMeshAdaptation(Input=mesh)  # noqa: F821 (defined by LoadPlugin)
    refined.RegionArrayName = options.region_array
    refined.NumberOfPartitions = options.partitions
    refined.EdgeLengthFactor = options.edge_length_factor
    refined.UpdatePipeline()
    info = refined.GetDataInformation()
    print("%s: %d -> %d cells, %d colours" % (
        options.input, mesh.GetDataInformation().GetNumberOfCells(), info.GetNumberOfCells(),
        refined.FieldData["NumberOfColors"].GetRange()[0]))
    if options.output:
        SaveData(options.output, proxy=refined)

    # Crinkle-clip half away (whole cells are kept) so that the partitions inside show too.
    bounds = info.GetBounds()
    clip = Clip(Input=refined)
    clip.ClipType = "Plane"
    clip.ClipType.Origin = [(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2,
                            (bounds[4] + bounds[5]) / 2]
    clip.ClipType.Normal = [0.0, 1.0, 0.0]
    clip.Crinkleclip = 1

    view = CreateView("RenderView")
    view.ViewSize = [1024, 768]
    display = Show(clip, view)
    display.SetRepresentationType("Surface With Edges")
    ColorBy(display, ("CELLS", "ColorId"))
    GetColorTransferFunction("ColorId").ApplyPreset("Rainbow Uniform", True)
    display.SetScalarBarVisibility(view, True)
    view.CameraPosition = [1.0, 2.0, 1.5]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    ResetCamera(view)
    Render(view)
    SaveScreenshot(options.screenshot, view, ImageResolution=[1024, 768])
    print("wrote " + options.screenshot)


if __name__ == "__main__":
    main()
