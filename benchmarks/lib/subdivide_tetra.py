#!/usr/bin/python3
"""VTK's vtkSubdivideTetra baseline on one input mesh, run as its own process (so that
/usr/bin/time measures its peak memory alone).

Usage: subdivide_tetra.py IN.vtu OUT.vtu RESULT.json

vtkSubdivideTetra splits every tetrahedron into 12 (edge midpoints and the centroid), each tet
on its own. It writes OUT (to measure its size; the caller deletes it) and RESULT: seconds of
the filter, counts, the quality summary and the conformity figures of lib.quality.conformity.
"""
import json
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

from vtkmodules.vtkFiltersModeling import vtkSubdivideTetra  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter  # noqa: E402

from lib import quality  # noqa: E402


def main(source, target, result_file):
    grid = quality.read_grid(source)
    start = time.perf_counter()
    subdivide = vtkSubdivideTetra()
    subdivide.SetInputData(grid)
    subdivide.Update()
    seconds = time.perf_counter() - start
    output = subdivide.GetOutput()
    start = time.perf_counter()
    writer = vtkXMLUnstructuredGridWriter()
    writer.SetFileName(target)
    writer.SetInputData(output)
    writer.SetDataModeToAppended()
    writer.EncodeAppendedDataOff()
    writer.SetCompressorTypeToZLib()   # as cgmesh writes its outputs
    writer.Write()
    write_seconds = time.perf_counter() - start
    edge_ratio, min_dihedral = quality.quality_arrays(output)
    result = {
        "seconds": seconds, "writeSeconds": write_seconds,
        "inputCells": int(grid.GetNumberOfCells()),
        "outputCells": int(output.GetNumberOfCells()),
        "outputPoints": int(output.GetNumberOfPoints()),
        "outputBytes": os.path.getsize(target),
        "cellArraysKept": [output.GetCellData().GetArrayName(i)
                           for i in range(output.GetCellData().GetNumberOfArrays())],
        "quality": quality.summarise(edge_ratio, min_dihedral),
        "conformity": quality.conformity(grid, output),
    }
    with open(result_file, "w") as handle:
        json.dump(result, handle)


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
