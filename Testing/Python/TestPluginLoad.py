"""Run with pvbatch: loads the built CoarseGrainedMesher plugin through paraview.simple and runs
the filter on a tetrahedralized Wavelet, checking counts and arrays."""
import argparse
import sys

from paraview import servermanager
from paraview.simple import LoadPlugin, Tetrahedralize, Wavelet

FAILURES = []


def check(condition, message):
    if not condition:
        FAILURES.append(message)
        print("check failed: " + message, file=sys.stderr)


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
    check(adaptation.NumberOfPartitions == 1024, "NumberOfPartitions default")
    check(adaptation.RegionArrayName == "None", "RegionArrayName default")
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
    for name in ("NumberOfColors", "NumberOfPartitions", "TotalSeconds"):
        check(refined.GetFieldData().GetArray(name) is not None, "field data %s missing" % name)

    if FAILURES:
        print("%d checks failed" % len(FAILURES), file=sys.stderr)
        return 1
    print("plugin loaded and filter ran: %d -> %d cells"
          % (source.GetNumberOfCells(), refined.GetNumberOfCells()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
