"""The filter under ParaView's MPI: `mpiexec -n 2` and `-n 3` pvbatch runs of DistributedPipeline
on the FinFET, the Big cube, a sliver-laden two-material box TetGen meshes without a quality
bound and Gmsh's two boxes and a ball, with both methods. The pieces each process writes are
gathered and merged by their global point ids, as a reader of a distributed mesh would: copies of
one id must have bit-identical coordinates, and the merged mesh must be valid and conforming (no
duplicate points, no face in three tets, no hanging face: the boundary area is the input's) with
the input's volume, region volumes and material-interface area. Global cell ids number the cells
0..N-1 once; ghost cells, when the writer asks for them, carry the ids of cells another process
owns. An input read on one process is spread first, with a note; 1 and 2 threads per process
write the same pieces; a piece that is not a tet mesh stops every process with a message,
instead of leaving the others waiting; and tagged triangles that RedistributeDataSet parts from
their tets are refused with the cause."""
import argparse
import glob
import os
import shutil
import subprocess
import sys

import numpy
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkUnstructuredGrid
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader, vtkXMLUnstructuredGridWriter

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import TestTaggedTriangles as tagged  # noqa: E402
from TestCommandLine import run  # noqa: E402

check = tagged.check
TETRA = 10
PIPELINE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "DistributedPipeline.py")
# mpiexec refuses to run as root (CI containers) unless told.
MPI_ENVIRONMENT = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                       OMPI_MCA_rmaps_base_oversubscribe="1")


def read_grid(path):
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def write_grid(points, tets, regions, region_array, path):
    grid = vtkUnstructuredGrid()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(numpy.ascontiguousarray(points), deep=1))
    grid.SetPoints(vtk_points)
    cells = vtkCellArray()
    cells.SetData(numpy_to_vtkIdTypeArray(numpy.arange(0, 4 * len(tets) + 1, 4), deep=1),
                  numpy_to_vtkIdTypeArray(numpy.ascontiguousarray(tets.ravel()), deep=1))
    grid.SetCells(TETRA, cells)
    if regions is not None:
        array = numpy_to_vtk(regions, deep=1)
        array.SetName(region_array)
        grid.GetCellData().AddArray(array)
    writer = vtkXMLUnstructuredGridWriter()
    writer.SetFileName(path)
    writer.SetInputData(grid)
    writer.Write()


def mesh_report(cgmesh, path, region_array):
    """`cgmesh check` figures as {name: text}."""
    arguments = ["check", path] + (["--region-array", region_array] if region_array else [])
    result = run(cgmesh, *arguments)
    report = {}
    for line in result.stdout.splitlines():
        words = line.rsplit(None, 1)
        if len(words) == 2:
            report[words[0].strip()] = words[1]
    report["valid"] = result.returncode == 0 and result.stdout.strip().endswith("valid")
    return report


def gather(directory, region_array, description):
    """(points, tets, regions, pieces) of the pieces merged by global point id; checks the ids."""
    coordinates, tets, regions, cell_ids, ghost_ids, pieces = {}, [], [], [], [], []
    for path in sorted(glob.glob(os.path.join(directory, "*.vtu"))):
        grid = read_grid(path)
        pieces.append(grid.GetNumberOfCells())
        if grid.GetNumberOfCells() == 0:
            continue
        point_ids = grid.GetPointData().GetGlobalIds()
        cell_id_array = grid.GetCellData().GetGlobalIds()
        check(point_ids is not None and point_ids.GetName() == "GlobalPointIds",
              description + ": no GlobalPointIds in " + path)
        check(cell_id_array is not None and cell_id_array.GetName() == "GlobalCellIds",
              description + ": no GlobalCellIds in " + path)
        if point_ids is None or cell_id_array is None:
            continue
        ids = vtk_to_numpy(point_ids)
        points = vtk_to_numpy(grid.GetPoints().GetData())
        connectivity = vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, 4)
        ghosts = grid.GetCellData().GetArray("vtkGhostType")
        owned = numpy.ones(len(connectivity), bool) if ghosts is None else \
            vtk_to_numpy(ghosts) == 0
        for point_id, point in zip(ids, points):
            known = coordinates.setdefault(int(point_id), point)
            if not numpy.array_equal(known, point):
                check(False, "%s: point id %d at %s and %s" % (description, point_id, known,
                                                               point))
                break
        tets.append(ids[connectivity[owned]])
        cell_ids.append(vtk_to_numpy(cell_id_array)[owned])
        ghost_ids.append(vtk_to_numpy(cell_id_array)[~owned])
        if region_array:
            regions.append(vtk_to_numpy(grid.GetCellData().GetArray(region_array))[owned])
    if not tets:
        check(False, description + ": every piece is empty")
        return numpy.zeros((0, 3)), numpy.zeros((0, 4), int), None, pieces, 0
    ids = numpy.array(sorted(coordinates))
    points = numpy.array([coordinates[i] for i in ids])
    tets = numpy.searchsorted(ids, numpy.concatenate(tets))
    cell_ids = numpy.concatenate(cell_ids)
    check(numpy.array_equal(numpy.sort(cell_ids), numpy.arange(len(cell_ids))),
          description + ": the owned cells' GlobalCellIds are not 0..N-1 once each")
    ghost_ids = numpy.concatenate(ghost_ids)
    check(numpy.isin(ghost_ids, cell_ids).all(),
          description + ": a ghost cell's id is no owned cell's")
    return points, tets, numpy.concatenate(regions) if region_array else None, pieces, \
        len(ghost_ids)


def refine_distributed(options, processes, source, directory, settings, redistribute=True,
                       ghost_level=0):
    shutil.rmtree(directory, ignore_errors=True)
    os.makedirs(directory)
    command = [options.mpiexec, "-n", str(processes), options.pvbatch, "--mpi", PIPELINE,
               "--plugin", options.plugin, "--input", source,
               "--output", os.path.join(directory, "out.pvtu"),
               "--ghost-level", str(ghost_level), "--set"] + settings
    if redistribute:
        command.append("--redistribute")
    return subprocess.run(command, capture_output=True, text=True, timeout=600,
                          env=MPI_ENVIRONMENT)


def same_figures(before, after, names, description):
    for name in names:
        a, b = float(before[name]), float(after[name])
        check(abs(a - b) <= 1e-9 * max(1.0, abs(a)),
              "%s: %s %s, input %s" % (description, name, b, a))


def test_case(options, description, processes, source, region_array, settings, **keywords):
    directory = os.path.join(options.scratch, description.replace(" ", "-").replace(",", ""))
    result = refine_distributed(options, processes, source, os.path.join(directory, "pieces"),
                                settings, **keywords)
    check(result.returncode == 0 and "ERR|" not in result.stdout + result.stderr,
          description + ": pvbatch: " + (result.stdout + result.stderr)[-3000:])
    if result.returncode != 0:
        return None
    points, tets, regions, pieces, ghosts = gather(
        os.path.join(directory, "pieces", "out"), region_array, description)
    check(len(pieces) == processes and min(pieces) > 0,
          "%s: cells per piece %s" % (description, pieces))
    merged = os.path.join(directory, "merged.vtu")
    write_grid(points, tets, regions, region_array, merged)
    before = mesh_report(options.cgmesh, source, region_array)
    after = mesh_report(options.cgmesh, merged, region_array)
    check(after["valid"], description + ": the merged mesh is not valid: %s" % after)
    for name in ("faces in 3+ tetrahedra", "duplicate points", "unused points",
                 "inverted tetrahedra", "degenerate tetrahedra", "misoriented face pairs"):
        check(after.get(name) == "0", "%s: %s %s" % (description, name, after.get(name)))
    names = ["volume", "boundary area"]
    if region_array:
        names += ["region interface area"] + [k for k in before if k.startswith("region ")
                                              and k[7:].isdigit()]
    same_figures(before, after, names, description)
    check(int(after["tetrahedra"]) > int(before["tetrahedra"]),
          description + ": nothing was refined")
    print("%s: %d processes, pieces %s, %s tets, %d ghost cells" % (
        description, processes, pieces, after["tetrahedra"], ghosts))
    return result, points, tets, ghosts


def make_inputs(options):
    finfet = os.path.join(options.scratch, "finfet.vtu")
    result = run(options.cgmesh, "generate", "finfet", finfet, "--cells", "30000")
    check(result.returncode == 0, "generate finfet: " + result.stderr)
    cube = os.path.join(options.scratch, "cube.vtu")
    result = run(options.cgmesh, "generate", "cube", "25", cube)
    check(result.returncode == 0, "generate cube: " + result.stderr)
    # Two materials, no quality bound: slivers everywhere, the interface among them.
    poly = os.path.join(options.scratch, "split-box.poly")
    with open(poly, "w") as handle:
        handle.write(tagged.TETGEN_POLY)
    result = subprocess.run([options.tetgen, "-pAa0.0005", poly], capture_output=True, text=True)
    check(result.returncode == 0, "tetgen: " + result.stdout[-1500:])
    box = tagged.read_tetgen(os.path.join(options.scratch, "split-box.1"))
    box_path = os.path.join(options.scratch, "split-box.vtu")
    write_grid(box.points, box.cells_dict["tetra"], box.cell_data["Tag"][0].astype(numpy.int32),
               "Tag", box_path)
    gmsh_source, gmsh_mesh = tagged.make_input(options.gmsh, options.scratch)
    gmsh_path = os.path.join(options.scratch, "two-volumes-tets.vtu")
    write_grid(gmsh_mesh.points, gmsh_mesh.cells_dict["tetra"],
               gmsh_mesh.cell_data_dict["Tag"]["tetra"].astype(numpy.int32), "Tag", gmsh_path)
    return finfet, cube, box_path, gmsh_path, gmsh_source


def test_bad_piece(options, finfet):
    """Two pieces, the second with a hexahedron: process 1 refuses it, and both processes stop."""
    pieces = os.path.join(options.scratch, "bad-pieces")
    shutil.rmtree(pieces, ignore_errors=True)
    os.makedirs(pieces)
    grid = read_grid(finfet)
    points = vtk_to_numpy(grid.GetPoints().GetData())
    tets = vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, 4)
    regions = vtk_to_numpy(grid.GetCellData().GetArray("Material"))
    half = len(tets) // 2
    write_grid(points, tets[:half], regions[:half], "Material", os.path.join(pieces, "p0.vtu"))
    bad = os.path.join(pieces, "p1.vtu")
    write_grid(points, tets[half:], regions[half:], "Material", bad)
    broken = read_grid(bad)
    broken.InsertNextCell(12, 8, list(range(8)))  # a hexahedron
    broken.GetCellData().GetArray("Material").InsertNextValue(0)
    writer = vtkXMLUnstructuredGridWriter()
    writer.SetFileName(bad)
    writer.SetInputData(broken)
    writer.Write()
    with open(os.path.join(pieces, "bad.pvtu"), "w") as handle:
        handle.write("""<?xml version="1.0"?>
<VTKFile type="PUnstructuredGrid" version="1.0" byte_order="LittleEndian">
<PUnstructuredGrid GhostLevel="0"><PCellData><PDataArray type="Int32" Name="Material"/>
</PCellData><PPoints><PDataArray type="Float64" NumberOfComponents="3"/></PPoints>
<Piece Source="p0.vtu"/><Piece Source="p1.vtu"/></PUnstructuredGrid></VTKFile>
""")
    result = refine_distributed(options, 2, os.path.join(pieces, "bad.pvtu"),
                                os.path.join(pieces, "out"), ["RegionArrayName=Material"],
                                redistribute=False)
    text = result.stdout + result.stderr
    check("HEXAHEDRON" in text.upper() and "only linear tetrahedra" in text,
          "bad piece: process 1's error is missing: " + text[-3000:])
    check("stopped on all 2 processes: process 1 failed" in text,
          "bad piece: process 0 does not say why it stopped: " + text[-3000:])
    written = sorted(glob.glob(os.path.join(pieces, "out", "out", "*.vtu")))
    check(all(read_grid(path).GetNumberOfCells() == 0 for path in written),
          "bad piece: a process wrote cells after the error")


def test_separated_triangles(options, gmsh_with_triangles):
    """RedistributeDataSet places the Gmsh mesh's tagged triangles apart from some of their tets:
    every process stops, and the one whose triangles lost their tets says what is needed."""
    result = refine_distributed(options, 2, gmsh_with_triangles,
                                os.path.join(options.scratch, "separated-triangles"),
                                ["RegionArrayName=Tag"])
    text = result.stdout + result.stderr
    check("not faces of its tetrahedra" in text and
          "must be in the piece that holds its tetrahedron" in text,
          "separated triangles: no error naming the cause: " + text[-3000:])


def main():
    parser = argparse.ArgumentParser()
    for name in ("mpiexec", "pvbatch", "plugin", "cgmesh", "tetgen", "gmsh", "scratch"):
        parser.add_argument("--" + name, required=True)
    options = parser.parse_args()
    shutil.rmtree(options.scratch, ignore_errors=True)
    os.makedirs(options.scratch)
    finfet, cube, box, gmsh, gmsh_with_triangles = make_inputs(options)
    if tagged.FAILURES:
        return 1
    material = ["RegionArrayName=Material", "NumberOfPartitions=16"]
    one = test_case(options, "finfet template 1 thread", 2, finfet, "Material",
                    material + ["NumberOfThreads=1"])
    two = test_case(options, "finfet template 2 threads", 2, finfet, "Material",
                    material + ["NumberOfThreads=2"])
    if one and two:
        check(numpy.array_equal(one[1], two[1]) and numpy.array_equal(one[2], two[2]),
              "finfet: 1 and 2 threads per process give different meshes")
    spread = test_case(options, "finfet delaunay read on one process", 3, finfet, "Material",
                       material + ["Method=Delaunay", "VolumeFactor=0.3"], redistribute=False)
    if spread:
        check("spread over all of them" in spread[0].stdout + spread[0].stderr,
              "finfet delaunay: no note that the input was spread")
    test_case(options, "cube template", 3, cube, None,
              ["NumberOfPartitions=64", "EdgeLengthFactor=0.8", "NumberOfIterations=2"])
    test_case(options, "cube delaunay", 2, cube, None,
              ["Method=Delaunay", "VolumeFactor=0.5", "NumberOfPartitions=32"])
    test_case(options, "tetgen slivers template", 2, box, "Tag",
              ["RegionArrayName=Tag", "EdgeLengthFactor=0.8", "NumberOfIterations=2"])
    test_case(options, "tetgen slivers delaunay", 3, box, "Tag",
              ["RegionArrayName=Tag", "Method=Delaunay", "VolumeFactor=0.5"])
    ghosts = test_case(options, "gmsh template ghost cells", 3, gmsh, "Tag",
                       ["RegionArrayName=Tag"], ghost_level=1)
    if ghosts:
        check(ghosts[3] > 0, "gmsh: ghost cells were asked for and none came")
    test_bad_piece(options, finfet)
    test_separated_triangles(options, gmsh_with_triangles)
    if tagged.FAILURES:
        print("%d failures" % len(tagged.FAILURES))
        return 1
    print("all distributed checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
