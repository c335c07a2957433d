"""Image regression test, run with pvbatch on an X server: the refined small FinFET coloured by
ColorId, with the isolation oxide left out and a crinkle clip through the middle so that the
partitions inside show, compared with Testing/Data/Baseline/FinFetColorId.png by
vtkImageDifference. Every parameter that shapes the picture is fixed here (one thread; the output
does not depend on the thread count anyway).

    pvbatch TestFinFetImage.py --plugin P --data finfet-small.vtu --baseline B.png --scratch DIR
    ... --generate-baseline   writes B.png instead of comparing (then look at it before committing)
"""
import argparse
import os
import shutil
import sys

from paraview.simple import (Clip, ColorBy, CreateView, Delete, GetColorTransferFunction,
                             LoadPlugin, Render, ResetCamera, SaveScreenshot, Show, Threshold,
                             XMLUnstructuredGridReader)
from vtkmodules.vtkImagingCore import vtkImageDifference
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter

ISOLATION_OXIDE = 8  # Material id of the oxide around the device (cgmesh generate finfet)
IMAGE_SIZE = [800, 600]
# vtkImageDifference's thresholded error, the metric of VTK's own regression tests (they fail
# above 10); anti-aliasing or driver differences stay far below, a different mesh does not.
ERROR_THRESHOLD = 10.0


def render(options, image_file):
    LoadPlugin(options.plugin, ns=globals())
    reader = XMLUnstructuredGridReader(FileName=[options.data])
    refined = CoarseGrainedMeshAdaptation(Input=reader)  # noqa: F821 (defined by LoadPlugin)
    refined.RegionArrayName = "Material"
    refined.NumberOfPartitions = 64
    refined.NumberOfIterations = 1
    refined.Method = "Template"
    refined.EdgeLengthFactor = 0.5
    refined.Partitioner = "METIS"  # compact parts: Hilbert runs, cut along grid planes, speckle a crinkle clip
    refined.ColoringAlgorithm = "Greedy-LU"
    refined.NumberOfThreads = 1
    if refined.GetProperty("ImproveQuality") is not None:
        refined.ImproveQuality = 0

    device = Threshold(Input=refined, Scalars=["CELLS", "Material"],
                       LowerThreshold=0, UpperThreshold=ISOLATION_OXIDE - 1)
    device.UpdatePipeline()
    bounds = device.GetDataInformation().GetBounds()
    centre = [(bounds[2 * axis] + bounds[2 * axis + 1]) / 2 for axis in range(3)]
    clip = Clip(Input=device)
    clip.ClipType = "Plane"
    clip.ClipType.Origin = centre
    clip.ClipType.Normal = [0.0, 1.0, 0.0]
    clip.Crinkleclip = 1

    view = CreateView("RenderView")
    view.ViewSize = IMAGE_SIZE
    view.OrientationAxesVisibility = 0
    display = Show(clip, view)
    display.SetRepresentationType("Surface With Edges")
    display.EdgeColor = [0.15, 0.15, 0.15]
    ColorBy(display, ("CELLS", "ColorId"))
    colors = GetColorTransferFunction("ColorId")
    colors.ApplyPreset("Rainbow Uniform", True)
    colors.RescaleTransferFunction(0.0, 8.0)
    # A fixed camera: looking at the cut face (it faces +y) from above, in front and to the side.
    size = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
    view.CameraFocalPoint = centre
    view.CameraPosition = [centre[0] + 0.9 * size, centre[1] + 1.6 * size, centre[2] + 1.0 * size]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30
    ResetCamera(view)
    view.GetActiveCamera().Dolly(1.1)
    Render(view)
    SaveScreenshot(image_file, view, ImageResolution=IMAGE_SIZE)
    # Release the render window while its X connection is still up: left to interpreter exit,
    # the teardown fails with GLXBadContext.
    Delete(view)


def read_png(file_name):
    reader = vtkPNGReader()
    reader.SetFileName(file_name)
    reader.Update()
    return reader.GetOutput()


def compare(image_file, baseline_file, scratch):
    difference = vtkImageDifference()
    difference.SetImageData(read_png(image_file))
    difference.SetInputData(read_png(baseline_file))
    difference.Update()
    error = difference.GetThresholdedError()
    print("image difference to %s: %.3f (threshold %.1f)" % (baseline_file, error,
                                                             ERROR_THRESHOLD))
    if error <= ERROR_THRESHOLD:
        return 0
    writer = vtkPNGWriter()
    writer.SetInputConnection(difference.GetOutputPort())
    writer.SetFileName(os.path.join(scratch, "FinFetColorId-difference.png"))
    writer.Write()
    print("image differs from the baseline; see %s" % scratch, file=sys.stderr)
    return 1


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--data", required=True)
    parser.add_argument("--baseline", required=True)
    parser.add_argument("--scratch", required=True)
    parser.add_argument("--generate-baseline", action="store_true")
    options, _ = parser.parse_known_args()
    os.makedirs(options.scratch, exist_ok=True)

    image_file = os.path.join(options.scratch, "FinFetColorId.png")
    render(options, image_file)
    if options.generate_baseline:
        shutil.copyfile(image_file, options.baseline)
        print("wrote baseline " + options.baseline)
        return 0
    if not os.path.isfile(options.baseline):
        print("no baseline %s (run with --generate-baseline)" % options.baseline, file=sys.stderr)
        return 1
    return compare(image_file, options.baseline, options.scratch)


if __name__ == "__main__":
    sys.exit(main())
