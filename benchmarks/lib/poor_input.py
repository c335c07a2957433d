"""The benchmarks' sliver-laden input: a block [0,4]x[0,2]x[0,1] (material 1) under a thin fin
[1.9,2.1]x[0,2]x[1,1.5] (material 2), filled with 4,000 pseudo-random points by TetGen without a
quality bound (`tetgen -pAi`): minimum dihedral angle about 0.003 degrees, 1st percentile about
0.6, large faces next to a thin feature. Written as a .vtu with the cell array `Material`."""
import os
import subprocess
import sys

import numpy
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import VTK_TETRA, vtkCellArray, vtkUnstructuredGrid
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter

DESCRIPTION = ("block and fin PLC filled with 4,000 random points by `tetgen -pAi` "
               "(2 materials, no quality bound)")


def write_fin_plc(path):
    points = [(0, 0, 0), (4, 0, 0), (4, 2, 0), (0, 2, 0), (0, 0, 1), (1.9, 0, 1), (2.1, 0, 1),
              (4, 0, 1), (0, 2, 1), (1.9, 2, 1), (2.1, 2, 1), (4, 2, 1), (1.9, 0, 1.5),
              (2.1, 0, 1.5), (1.9, 2, 1.5), (2.1, 2, 1.5)]
    # One polygon per facet; the fin's front and back are facets of their own, so that the
    # block/fin interface edges are facet edges.
    facets = [[1, 2, 3, 4], [1, 2, 8, 7, 6, 5], [6, 7, 14, 13], [4, 3, 12, 11, 10, 9],
              [10, 11, 16, 15], [1, 4, 9, 5], [2, 3, 12, 8], [5, 6, 10, 9], [7, 8, 12, 11],
              [6, 7, 11, 10], [6, 13, 15, 10], [7, 14, 16, 11], [13, 14, 16, 15]]
    with open(path, "w") as out:
        out.write("%d 3 0 0\n" % len(points))
        for index, point in enumerate(points, 1):
            out.write("%d %r %r %r\n" % ((index,) + tuple(float(x) for x in point)))
        out.write("%d 0\n" % len(facets))
        for facet in facets:
            out.write("1\n%d %s\n" % (len(facet), " ".join(map(str, facet))))
        out.write("0\n2\n1 1.0 1.0 0.5 1 -1\n2 2.0 1.0 1.25 2 -1\n")


def write_random_points(path, seed=7):
    generator = numpy.random.default_rng(seed)
    block = generator.random((3500, 3)) * [4, 2, 1]
    fin = generator.random((500, 3)) * [0.2, 2, 0.5] + [1.9, 0, 1]
    points = numpy.vstack([block, fin])
    with open(path, "w") as out:
        out.write("%d 3 0 0\n" % len(points))
        for index, point in enumerate(points, 1):
            out.write("%d %r %r %r\n" % (index, point[0], point[1], point[2]))


def read_tetgen_mesh(stem, output):
    """TetGen's .node/.ele (with a region attribute) as a .vtu with the cell array Material."""
    def rows(path):
        with open(path) as handle:
            return [line.split() for line in handle
                    if line.strip() and not line.lstrip().startswith("#")]
    nodes, elements = rows(stem + ".node"), rows(stem + ".ele")
    count, first = int(nodes[0][0]), int(nodes[1][0])
    points = numpy.array([[float(x) for x in row[1:4]] for row in nodes[1:count + 1]])
    tets = int(elements[0][0])
    corners = numpy.array([[int(x) - first for x in row[1:5]] for row in elements[1:tets + 1]],
                          dtype=numpy.int64)
    material = numpy.array([int(float(row[5])) for row in elements[1:tets + 1]],
                           dtype=numpy.int32)
    grid = vtkUnstructuredGrid()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(points, deep=True))
    grid.SetPoints(vtk_points)
    cells = vtkCellArray()
    cells.SetData(numpy_to_vtkIdTypeArray(numpy.arange(0, 4 * tets + 1, 4, dtype=numpy.int64),
                                          deep=True),
                  numpy_to_vtkIdTypeArray(corners.ravel(), deep=True))
    grid.SetCells(VTK_TETRA, cells)
    array = numpy_to_vtk(material, deep=True)
    array.SetName("Material")
    grid.GetCellData().AddArray(array)
    writer = vtkXMLUnstructuredGridWriter()
    writer.SetFileName(output)
    writer.SetInputData(grid)
    if not writer.Write():
        sys.exit("could not write " + output)


def make_poor_input(folder, path):
    """Writes the sliver-laden input to `path`, TetGen's files to `folder`."""
    stem = os.path.join(folder, "fin")
    write_fin_plc(stem + ".poly")
    write_random_points(stem + ".a.node")
    command = ["tetgen", "-pAiQ", stem + ".poly"]
    print("running: " + " ".join(command), file=sys.stderr, flush=True)
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit("%s failed: %s" % (" ".join(command), result.stderr.strip()))
    read_tetgen_mesh(stem + ".1", path)
