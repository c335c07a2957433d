"""An Exodus mesh refined in ParaView as a GUI user does it (run by pvbatch): the IOSS reader with
the side sets switched on, Merge Blocks, then the filter. The file is TestTaggedTriangles' Gmsh
mesh written by `cgmesh refine` as .exo. The output must hold the side sets as triangles, each
side set's area and vector area and each block's volume as read, and the reader's global node ids
extended: every input node keeps its id (side set nodes their coordinates too), and new nodes are
numbered on from the largest."""
import argparse
import os
import shutil
import sys

import numpy
from paraview import servermanager
from paraview.simple import IOSSReader, LoadPlugin, MergeBlocks
from vtkmodules.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import TestTaggedTriangles as tagged  # noqa: E402
from TestCommandLine import run  # noqa: E402

check = tagged.check
TETRA, TRIANGLE = 10, 5


def figures(grid):
    """({object_id: volume} of the tets, {object_id: (area, vector area)} of the triangles)."""
    points = vtk_to_numpy(grid.GetPoints().GetData())
    offsets = vtk_to_numpy(grid.GetCells().GetOffsetsArray())
    connectivity = vtk_to_numpy(grid.GetCells().GetConnectivityArray())
    types = vtk_to_numpy(grid.GetCellTypesArray())
    ids = vtk_to_numpy(grid.GetCellData().GetArray("object_id"))
    starts = offsets[:-1]
    tets = numpy.array([connectivity[s:s + 4] for s in starts[types == TETRA]])
    triangles = numpy.array([connectivity[s:s + 3] for s in starts[types == TRIANGLE]])
    p = points[tets]
    volumes = numpy.abs(numpy.einsum("ij,ij->i", p[:, 1] - p[:, 0], numpy.cross(
        p[:, 2] - p[:, 0], p[:, 3] - p[:, 0]))) / 6
    q = points[triangles]
    normals = 0.5 * numpy.cross(q[:, 1] - q[:, 0], q[:, 2] - q[:, 0])
    tet_ids, triangle_ids = ids[types == TETRA], ids[types == TRIANGLE]
    return ({int(k): volumes[tet_ids == k].sum() for k in numpy.unique(tet_ids)},
            {int(k): (numpy.linalg.norm(normals[triangle_ids == k], axis=1).sum(),
                      normals[triangle_ids == k].sum(axis=0)) for k in numpy.unique(triangle_ids)})


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--cgmesh", required=True)
    parser.add_argument("--gmsh", default="gmsh")
    parser.add_argument("--scratch", required=True)
    options = parser.parse_args()
    shutil.rmtree(options.scratch, ignore_errors=True)
    os.makedirs(options.scratch)
    source, _ = tagged.make_input(options.gmsh, options.scratch)
    exo = os.path.join(options.scratch, "two-volumes.exo")
    result = run(options.cgmesh, "refine", source, exo, "--partitions", "8")
    check(result.returncode == 0, "cgmesh refine to .exo: " + result.stderr)
    if tagged.FAILURES:
        return 1

    LoadPlugin(options.plugin, ns=globals())
    reader = IOSSReader(FileName=[exo])
    reader.UpdatePipelineInformation()
    reader.SideSets = list(reader.GetProperty("SideSetInfo")[::2])
    merged = MergeBlocks(Input=reader)
    adaptation = CoarseGrainedMeshAdaptation(Input=merged)  # noqa: F821 (from LoadPlugin)
    adaptation.NumberOfPartitions = 8
    adaptation.UpdatePipeline()
    before = servermanager.Fetch(merged)
    after = servermanager.Fetch(adaptation)

    volumes_before, surfaces_before = figures(before)
    volumes_after, surfaces_after = figures(after)
    check(sorted(surfaces_before) == [11, 12, 13, 14] and
          sorted(surfaces_after) == sorted(surfaces_before),
          "side sets %s, then %s" % (sorted(surfaces_before), sorted(surfaces_after)))
    for key, (area, vector) in surfaces_before.items():
        area_after, vector_after = surfaces_after.get(key, (0.0, numpy.zeros(3)))
        check(abs(area_after - area) <= 1e-12 * area and
              numpy.linalg.norm(vector_after - vector) <= 1e-12 * area,
              "side set %d: area %.15g, vector %s; before %.15g, %s"
              % (key, area_after, vector_after, area, vector))
    check(sorted(volumes_before) == [1, 2, 3] and sorted(volumes_after) == [1, 2, 3],
          "blocks %s, then %s" % (sorted(volumes_before), sorted(volumes_after)))
    for key, volume in volumes_before.items():
        check(abs(volumes_after.get(key, 0) - volume) <= 1e-12 * volume,
              "block %d volume %.15g, before %.15g" % (key, volumes_after.get(key, 0), volume))

    ids_before = before.GetPointData().GetGlobalIds()
    ids_after = after.GetPointData().GetGlobalIds()
    check(ids_before is not None and ids_after is not None, "no global point ids")
    if ids_before is not None and ids_after is not None:
        old_ids, new_ids = vtk_to_numpy(ids_before), vtk_to_numpy(ids_after)
        top = old_ids.max()
        check(numpy.array_equal(numpy.sort(new_ids), numpy.concatenate(
            [numpy.sort(old_ids), numpy.arange(top + 1, top + 1 + len(new_ids) - len(old_ids))])),
            "global point ids: not the input's extended by %d..%d"
            % (top + 1, top + len(new_ids) - len(old_ids)))
        # Nodes on the side sets never move: they keep their coordinates with their ids.
        position = dict(zip(new_ids.tolist(), vtk_to_numpy(after.GetPoints().GetData())))
        points = vtk_to_numpy(before.GetPoints().GetData())
        types = vtk_to_numpy(before.GetCellTypesArray())
        offsets = vtk_to_numpy(before.GetCells().GetOffsetsArray())[:-1]
        connectivity = vtk_to_numpy(before.GetCells().GetConnectivityArray())
        on_sides = numpy.unique(numpy.concatenate(
            [connectivity[s:s + 3] for s in offsets[types == TRIANGLE]]))
        moved = [int(old_ids[p]) for p in on_sides
                 if not numpy.array_equal(position.get(int(old_ids[p])), points[p])]
        check(not moved, "%d side set nodes moved or lost their id (the first: %s)"
              % (len(moved), moved[:3]))
    if tagged.FAILURES:
        print("%d checks failed" % len(tagged.FAILURES), file=sys.stderr)
        return 1
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
