"""Run by the ParaView GUI (paraview --script=...) in the GUI smoke test: loads the plugin,
applies the filter to the FinFET, shows it coloured by ColorId in the GUI's render view, saves a
screenshot and writes the output cell count. Parameters come from CGMESH_GUI_* environment
variables because --script passes no arguments; the file named by CGMESH_GUI_DONE is written
last, telling the test driver that the GUI has done its work."""
import os

from paraview.simple import (Clip, ColorBy, GetActiveViewOrCreate, GetColorTransferFunction,
                             LoadPlugin, OpenDataFile, Render, ResetCamera, SaveScreenshot,
                             SetActiveSource, Show, Threshold)

LoadPlugin(os.environ["CGMESH_GUI_PLUGIN"], ns=globals())
mesh = OpenDataFile(os.environ["CGMESH_GUI_DATA"])
refined = CoarseGrainedMeshAdaptation(Input=mesh)  # noqa: F821 (defined by LoadPlugin)
refined.RegionArrayName = "Material"
refined.NumberOfPartitions = 64
refined.EdgeLengthFactor = 0.5
refined.NumberOfThreads = 1
refined.UpdatePipeline()

# Leave the isolation oxide (Material 8) out and crinkle-clip the device open, as a user would.
device = Threshold(Input=refined, Scalars=["CELLS", "Material"], LowerThreshold=0,
                   UpperThreshold=7)
device.UpdatePipeline()
bounds = device.GetDataInformation().GetBounds()
clip = Clip(Input=device)
clip.ClipType = "Plane"
clip.ClipType.Origin = [(bounds[2 * axis] + bounds[2 * axis + 1]) / 2 for axis in range(3)]
clip.ClipType.Normal = [0.0, 1.0, 0.0]
clip.Crinkleclip = 1
SetActiveSource(refined)  # the Properties panel shows the filter's parameters

view = GetActiveViewOrCreate("RenderView")
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
SaveScreenshot(os.environ["CGMESH_GUI_SCREENSHOT"], view, ImageResolution=[1024, 768])

with open(os.environ["CGMESH_GUI_COUNT"], "w") as count_file:
    count_file.write("%d\n" % refined.GetDataInformation().GetNumberOfCells())
with open(os.environ["CGMESH_GUI_DONE"], "w") as done_file:
    done_file.write("done\n")
