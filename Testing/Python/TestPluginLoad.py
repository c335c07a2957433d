"""Run with pvbatch: loads the built CoarseGrainedMesher plugin through paraview.simple and runs
the filter on a tetrahedralized Wavelet, checking counts and arrays, with the colouring chosen by
its label in the drop-down; then the Delaunay method, chosen by its label, on a small cube, and the
refinement box set through the box widget's properties."""
import argparse
import sys

from paraview import servermanager
from paraview.simple import LoadPlugin, Tetrahedralize, Wavelet

FAILURES = []


def check(condition, message):
    if not condition:
        FAILURES.append(message)
        print("check failed: " + message, file=sys.stderr)


def test_delaunay():
    """Method chosen by its drop-down label on a tetrahedralized 10^3-voxel cube."""
    cube = Tetrahedralize(Input=Wavelet(WholeExtent=[0, 10, 0, 10, 0, 10]))
    adaptation = CoarseGrainedMeshAdaptation(Input=cube)  # noqa: F821 (from LoadPlugin)
    check(adaptation.Method == "Template", "Method default: %s" % adaptation.Method)
    labels = adaptation.GetProperty("Method").Available
    check(list(labels) == ["Template", "Delaunay"], "Method labels: %s" % labels)
    check(adaptation.MaximumVolume == 0 and adaptation.VolumeFactor == 0.1
          and adaptation.RadiusEdgeRatio == 2.0, "Delaunay property defaults")
    adaptation.Method = "Delaunay"
    adaptation.NumberOfPartitions = 16
    adaptation.VolumeFactor = 0.2
    adaptation.NumberOfThreads = 2
    adaptation.Diagnostics = 1
    adaptation.UpdatePipeline()

    source = servermanager.Fetch(cube)
    refined = servermanager.Fetch(adaptation)
    check(refined.GetNumberOfCells() > 2 * source.GetNumberOfCells(),
          "Delaunay: %d -> %d cells" % (source.GetNumberOfCells(), refined.GetNumberOfCells()))
    method = refined.GetFieldData().GetAbstractArray("Method")
    check(method is not None and method.GetValue(0) == "delaunay",
          "the filter did not run the method chosen by label")
    for name in ("VolumeBound", "DelaunayFallbacks", "TetGenPoints", "FallbackPartitions"):
        check(refined.GetFieldData().GetArray(name) is not None, "field data %s missing" % name)
    check(refined.GetFieldData().GetArray("VolumeBound").GetValue(0) > 0, "VolumeBound not > 0")
    check(refined.GetPointData().GetArray("RTData") is not None, "Delaunay: point data lost")
    print("Delaunay: %d -> %d cells" % (source.GetNumberOfCells(), refined.GetNumberOfCells()))


def test_refinement_box_widget():
    """The box widget's properties start at the input's bounds (their domains) and refine as
    the same box given as RefinementBox text does."""
    cube = Tetrahedralize(Input=Wavelet(WholeExtent=[0, 6, 0, 6, 0, 6]))
    cube.UpdatePipeline()  # the domains read the input's bounds, as in the GUI after Apply
    widget = CoarseGrainedMeshAdaptation(Input=cube)  # noqa: F821 (from LoadPlugin)
    check(widget.RefinementBoxEnabled == 0, "RefinementBoxEnabled default")
    check(list(widget.RefinementBoxOrigin) == [0.0, 0.0, 0.0]
          and list(widget.RefinementBoxLength) == [6.0, 6.0, 6.0],
          "box widget defaults: origin %s, length %s (input bounds 0..6)"
          % (list(widget.RefinementBoxOrigin), list(widget.RefinementBoxLength)))
    widget.RefinementBoxEnabled = 1
    widget.RefinementBoxOrigin = [0.0, 0.0, 0.0]
    widget.RefinementBoxLength = [2.0, 6.0, 6.0]
    widget.NumberOfPartitions = 8
    text = CoarseGrainedMeshAdaptation(Input=cube)  # noqa: F821 (from LoadPlugin)
    text.RefinementBox = "0,0,0,2,6,6"
    text.NumberOfPartitions = 8
    counts = [servermanager.Fetch(proxy).GetNumberOfCells() for proxy in (cube, widget, text)]
    check(counts[0] < counts[1] < 8 * counts[0] and counts[1] == counts[2],
          "box widget: %d -> %d cells, as text %d" % tuple(counts))
    print("box widget: %d -> %d cells (as text: %d)" % tuple(counts))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--scratch", required=False)
    options, _ = parser.parse_known_args()

    LoadPlugin(options.plugin, ns=globals())
    prototype = servermanager.ProxyManager().GetPrototypeProxy(
        "filters", "CoarseGrainedMeshAdaptation")
    check(prototype is not None, "proxy CoarseGrainedMeshAdaptation not registered")
    check(prototype.GetXMLLabel() == "Coarse-Grained Mesh Adaptation", "GUI label")

    wavelet = Wavelet(WholeExtent=[0, 4, 0, 4, 0, 4])
    tetrahedra = Tetrahedralize(Input=wavelet)
    adaptation = CoarseGrainedMeshAdaptation(Input=tetrahedra)  # noqa: F821 (from LoadPlugin)
    check(adaptation.NumberOfPartitions == 0, "NumberOfPartitions default (automatic)")
    check(adaptation.RegionArrayName == "None", "RegionArrayName default")
    check(adaptation.ColoringAlgorithm == "Greedy-LU",
          "ColoringAlgorithm default: %s" % adaptation.ColoringAlgorithm)
    labels = adaptation.GetProperty("ColoringAlgorithm").Available
    check(list(labels) == ["Greedy", "Greedy-LU", "Iterative", "Recoloring"],
          "ColoringAlgorithm labels: %s" % labels)
    check(adaptation.PartitionByRegion == 0, "PartitionByRegion default")
    check(adaptation.PartitionsPerRegion == 1, "PartitionsPerRegion default")
    check(adaptation.MaximumNumberOfCells == 100000000,
          "MaximumNumberOfCells default: %s" % adaptation.MaximumNumberOfCells)
    adaptation.ColoringAlgorithm = "Recoloring"
    adaptation.NumberOfPartitions = 8
    adaptation.NumberOfIterations = 1
    adaptation.EdgeLengthFactor = 0.25  # below every edge of the tetrahedralized voxels
    adaptation.NumberOfThreads = 2
    adaptation.UpdatePipeline()

    source = servermanager.Fetch(tetrahedra)
    refined = servermanager.Fetch(adaptation)
    check(refined.GetNumberOfCells() == 8 * source.GetNumberOfCells(),
          "expected %d cells, got %d" % (8 * source.GetNumberOfCells(), refined.GetNumberOfCells()))
    for name in ("PartitionId", "ColorId", "EdgeRatio", "MinDihedralAngle"):
        check(refined.GetCellData().GetArray(name) is not None, "cell array %s missing" % name)
    check(refined.GetPointData().GetArray("RTData") is not None, "point data not interpolated")
    for name in ("NumberOfColors", "NumberOfPartitions", "TotalSeconds", "PartitionsPerColor",
                 "CellsPerColor", "ColorBalance"):
        check(refined.GetFieldData().GetArray(name) is not None, "field data %s missing" % name)
    check(refined.GetFieldData().GetArray("ColoringAlgorithmIndex").GetValue(0) == 3,
          "the filter did not run the colouring chosen by label")
    check(refined.GetFieldData().GetAbstractArray("ColoringAlgorithm") is None,
          "a text diagnostic in the field data without Diagnostics")

    test_delaunay()
    test_refinement_box_widget()
    if FAILURES:
        print("%d checks failed" % len(FAILURES), file=sys.stderr)
        return 1
    print("plugin loaded and filter ran: %d -> %d cells"
          % (source.GetNumberOfCells(), refined.GetNumberOfCells()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
