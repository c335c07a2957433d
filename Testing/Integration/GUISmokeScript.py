"""Run by the ParaView GUI (paraview --script=...) in the GUI smoke test: loads the plugin,
applies the filter to the FinFET, shows it coloured by ColorId in the GUI's render view, saves a
screenshot and writes the output cell count; then applies it again with a refinement box set
through the box widget's properties and writes that cell count and the box. Parameters come from
CGMESH_GUI_* environment variables because --script passes no arguments; the file named by
CGMESH_GUI_DONE is written last, telling the test driver that the GUI has done its work."""
import os

from paraview.simple import (Clip, ColorBy, GetActiveCamera, GetActiveViewOrCreate,
                             GetColorTransferFunction, Hide, LoadPlugin, OpenDataFile, Render,
                             ResetCamera, SaveScreenshot, SetActiveSource, Show, Threshold)

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

# The refinement box placed through the box widget's properties (the lower x half of the
# device), shown in place of the first run with the oxide left out, and left as the active source
# so that the Properties panel builds the box widget, which the view draws around the refined half
# (the window screenshot of --window-screenshot, docs/finfet-gui.png).
mesh_bounds = mesh.GetDataInformation().GetBounds()
boxed = CoarseGrainedMeshAdaptation(Input=mesh)  # noqa: F821 (defined by LoadPlugin)
boxed.RegionArrayName = "Material"
boxed.NumberOfPartitions = 64
boxed.EdgeLengthFactor = 0.5
boxed.NumberOfThreads = 1
boxed.RefinementBoxEnabled = 1
origin = [mesh_bounds[0], mesh_bounds[2], mesh_bounds[4]]
length = [(mesh_bounds[1] - mesh_bounds[0]) / 2, mesh_bounds[3] - mesh_bounds[2],
          mesh_bounds[5] - mesh_bounds[4]]
boxed.RefinementBoxOrigin = origin
boxed.RefinementBoxLength = length
boxed.UpdatePipeline()
boxed_device = Threshold(Input=boxed, Scalars=["CELLS", "Material"], LowerThreshold=0,
                         UpperThreshold=7)
Hide(clip, view)
boxed_display = Show(boxed_device, view)
boxed_display.SetRepresentationType("Surface With Edges")
ColorBy(boxed_display, ("CELLS", "Material"))
view.CameraPosition = [1.0, -2.0, 1.2]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
ResetCamera(view)
GetActiveCamera().Dolly(0.8)
SetActiveSource(boxed)
Render(view)

with open(os.environ["CGMESH_GUI_COUNT"], "w") as count_file:
    count_file.write("%d\n" % refined.GetDataInformation().GetNumberOfCells())
    # The box as the command line's --refine-box takes it: the same doubles (repr round-trips).
    count_file.write("%d %s\n" % (boxed.GetDataInformation().GetNumberOfCells(), ",".join(
        repr(value) for value in origin + [o + l for o, l in zip(origin, length)])))
with open(os.environ["CGMESH_GUI_DONE"], "w") as done_file:
    done_file.write("done\n")
