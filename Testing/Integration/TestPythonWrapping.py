"""The wrapped VTK module from Python: `from cgmesh import vtkCoarseGrainedMeshAdaptation`.

Run by ctest under /usr/bin/python3 and under pvbatch, with the build tree's Python package on
PYTHONPATH. Builds a tetrahedralized 4^3-voxel block with a region array in plain VTK, refines it
with every edge split and checks the counts, the arrays and that the thread count does not change
the result.
"""
import sys

from vtkmodules.vtkCommonCore import vtkIntArray
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter

from cgmesh import vtkCoarseGrainedMeshAdaptation

FAILURES = []


def check(condition, message):
    if not condition:
        FAILURES.append(message)
        print("check failed: " + message, file=sys.stderr)


def make_tet_block(voxels):
    """Unit voxels cut into conforming tetrahedra, with a cell array Material: 1 for x < half."""
    image = vtkImageData()
    image.SetDimensions(voxels + 1, voxels + 1, voxels + 1)
    tetrahedralize = vtkDataSetTriangleFilter()
    tetrahedralize.SetInputData(image)
    tetrahedralize.Update()
    grid = tetrahedralize.GetOutput()

    material = vtkIntArray()
    material.SetName("Material")
    for cell in range(grid.GetNumberOfCells()):
        points = grid.GetCell(cell).GetPoints()
        x = sum(points.GetPoint(i)[0] for i in range(4)) / 4
        material.InsertNextValue(1 if x < voxels / 2 else 2)
    grid.GetCellData().AddArray(material)
    return grid


def refine(grid, threads):
    adaptation = vtkCoarseGrainedMeshAdaptation()
    adaptation.SetInputData(grid)
    adaptation.SetNumberOfPartitions(8)
    adaptation.SetMaximumEdgeLength(0.5)  # below every edge of the unit voxels: all are split
    adaptation.SetRegionArrayName("Material")
    adaptation.SetColoringAlgorithmToRecoloring()
    adaptation.SetNumberOfThreads(threads)
    adaptation.Update()
    return adaptation.GetOutput()


def cell_array_values(grid, name):
    array = grid.GetCellData().GetArray(name)
    return [array.GetTuple1(i) for i in range(array.GetNumberOfTuples())]


def main():
    adaptation = vtkCoarseGrainedMeshAdaptation()
    check(adaptation.GetNumberOfPartitions() == 0, "NumberOfPartitions default (automatic)")
    check(adaptation.GetMethodName() == "template", "Method default")
    check(adaptation.IsA("vtkUnstructuredGridAlgorithm"), "base class")

    grid = make_tet_block(4)
    refined = refine(grid, 1)
    expected = 8 * grid.GetNumberOfCells()
    check(refined.GetNumberOfCells() == expected,
          "expected %d cells, got %d" % (expected, refined.GetNumberOfCells()))
    for name in ("PartitionId", "ColorId", "EdgeRatio", "MinDihedralAngle", "Material"):
        check(refined.GetCellData().GetArray(name) is not None, "cell array %s missing" % name)
    field = refined.GetFieldData()
    check(field.GetArray("NumberOfColors").GetValue(0) >= 2, "NumberOfColors")
    check(field.GetArray("ColoringAlgorithmIndex").GetValue(0) == 3,
          "ColoringAlgorithmIndex in field data")
    # Each region's cells keep their id: the refined material volumes are those of the input.
    materials = cell_array_values(refined, "Material")
    check(materials.count(1) == materials.count(2), "material split %d / %d"
          % (materials.count(1), materials.count(2)))

    threaded = refine(grid, 2)
    check(threaded.GetNumberOfPoints() == refined.GetNumberOfPoints()
          and cell_array_values(threaded, "ColorId") == cell_array_values(refined, "ColorId"),
          "1 and 2 threads differ")

    if FAILURES:
        print("%d checks failed" % len(FAILURES), file=sys.stderr)
        return 1
    print("cgmesh from %s: %d -> %d cells" % (sys.executable, grid.GetNumberOfCells(),
                                              refined.GetNumberOfCells()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
