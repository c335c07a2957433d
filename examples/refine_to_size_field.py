"""Refine the FinFET to a size field made from a doping-like profile with ParaView's Calculator,
then cut it open and save a screenshot coloured by EdgeLengthRatio: the paraview.simple way.

    xvfb-run -a -s '-screen 0 1280x1024x24' pvbatch examples/refine_to_size_field.py \
        Data/finfet-small.vtu finfet-size-field.png

On a finer FinFET, scale the sizes down with --size-scale (0.35 for the 837,584-tet one of
`cgmesh generate finfet`): coarsening never removes a vertex of a material interface, so an
input finer than h there stays so.

The first Calculator writes a point array Doping (cm^-3): n+ source and drain (1e20) that fall
off into the channel with a 3 nm Gaussian from x = 18 and x = 42 nm, on a 1e16 background inside
the fin, decaying to 1e15 outside it. The second turns it into a target edge length h (nm), the
way a TCAD user grades a mesh by doping: smallest (0.8 nm) where log10(Doping) crosses 18 (the
junctions), larger on the plateaus, growing with the distance from the fin, at most 3 nm (about
the input's own edge length, so the substrate and isolation are left as they are). The filter
refines to h (SizeArrayName) until a pass changes nothing. The device geometry is that of
`cgmesh generate finfet` (Generators/FinFetLayout.cxx): x 0..60 (source | gate | drain), the fin
at |y| < 5 and 30 < z < 60.

(xvfb-run only on a machine without a display.) --plugin defaults to the plugin in this
checkout's build/ directory; pass the installed
lib/paraview-5.11/plugins/CoarseGrainedMesher/CoarseGrainedMesher.so otherwise.
"""
import argparse
import os

from paraview.simple import (Calculator, Clip, ColorBy, CreateView, GetColorTransferFunction,
                             LoadPlugin, OpenDataFile, Render, ResetCamera, SaveData,
                             SaveScreenshot, Show)

REPOSITORY = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD_TREE_PLUGIN = os.path.join(REPOSITORY, "build", "lib", "paraview-5.11", "plugins",
                                 "CoarseGrainedMesher", "CoarseGrainedMesher.so")

# Calculator expressions (ExprTk): coordsX/Y/Z are the point coordinates in nanometres.
FIN = ("exp(-(max(abs(coordsY)-5,0)/2)^2)*exp(-(max(30-coordsZ,0)/2)^2)*"
       "exp(-(max(coordsZ-60,0)/2)^2)")
DOPING = ("(1e16 + 1e20*exp(-(max(coordsX-18,0)/3)^2) + 1e20*exp(-(max(42-coordsX,0)/3)^2))*"
          + FIN + " + 1e15")
DISTANCE_FROM_FIN = "(max(abs(coordsY)-5,0) + max(30-coordsZ,0) + max(coordsZ-60,0))"
SIZE = "min(3, 0.8 + 0.4*abs(log10(Doping)-18) + 0.25*" + DISTANCE_FROM_FIN + ")"


def size_expression(scale):
    """SIZE times `scale` (1: for Data/finfet-small.vtu, whose edges are about 3 nm)."""
    return SIZE if scale == 1 else "%r*%s" % (scale, SIZE)


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("input", help="the FinFET (.vtu with the cell array Material)")
    parser.add_argument("screenshot", help="PNG to write")
    parser.add_argument("--plugin", default=BUILD_TREE_PLUGIN, help="CoarseGrainedMesher.so")
    parser.add_argument("--threads", type=int, default=0, help="0: every core")
    parser.add_argument("--size-scale", type=float, default=1.0,
                        help="multiplies h: below 1 for a finer input (its short edges on "
                        "material interfaces cannot be coarsened)")
    parser.add_argument("--output", help="also save the refined mesh (.vtu)")
    # pvbatch passes its own options through to the script: ignore those.
    options, _ = parser.parse_known_args()
    return options


def point_calculator(source, name, expression):
    """A point-data Calculator. The attribute type is set before the expression: the expression
    is checked against the variables of the attribute type at hand."""
    calculator = Calculator(Input=source)
    calculator.AttributeType = "Point Data"
    calculator.ResultArrayName = name
    calculator.Function = expression
    return calculator


def main():
    options = parse_arguments()
    # ns=globals() makes the plugin's filter a paraview.simple function of this module.
    LoadPlugin(options.plugin, ns=globals())

    mesh = OpenDataFile(options.input)
    doping = point_calculator(mesh, "Doping", DOPING)
    size = point_calculator(doping, "h", size_expression(options.size_scale))
    refined = CoarseGrainedMeshAdaptation(Input=size)  # noqa: F821 (defined by LoadPlugin)
    refined.RegionArrayName = "Material"
    refined.SizeArrayName = "h"
    refined.NumberOfIterations = 10  # passes stop once one adds no point
    refined.NumberOfThreads = options.threads
    refined.UpdatePipeline()
    info = refined.GetDataInformation()
    field = refined.FieldData
    print("%s: %d -> %d cells, h in [%.3g, %.3g] nm, %d passes (%s), "
          "EdgesWithinSizeBounds %.4f, %d edge collapses, %.2f s" % (
              options.input, mesh.GetDataInformation().GetNumberOfCells(),
              info.GetNumberOfCells(), *size.PointData["h"].GetRange(),
              field["IterationsRun"].GetRange()[0],
              "converged" if field["RefinementConverged"].GetRange()[0] else "iteration limit",
              field["EdgesWithinSizeBounds"].GetRange()[0],
              field["EdgeCollapses"].GetRange()[0], field["TotalSeconds"].GetRange()[0]))
    if options.output:
        SaveData(options.output, proxy=refined)

    # Crinkle-clip the half in front of the fin's mid-plane away (whole cells are kept), so that
    # the graded tets inside the fin show.
    clip = Clip(Input=refined)
    clip.ClipType = "Plane"
    clip.ClipType.Origin = [30.0, 0.0, 45.0]
    clip.ClipType.Normal = [0.0, 1.0, 0.0]
    clip.Crinkleclip = 1

    view = CreateView("RenderView")
    view.ViewSize = [1024, 768]
    display = Show(clip, view)
    display.SetRepresentationType("Surface With Edges")
    ColorBy(display, ("CELLS", "EdgeLengthRatio"))
    ratio = GetColorTransferFunction("EdgeLengthRatio")
    ratio.ApplyPreset("Cool to Warm", True)
    ratio.RescaleTransferFunction(0.5, 2.0)  # longest edge over h; 1.41 is the split bound
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
