"""Exodus II files through `cgmesh refine`, checked by a reader that shares no code with cgmesh's:
ParaView's IOSS reader (Sandia's IOSS library over netCDF).

The mesh is TestTaggedTriangles' Gmsh mesh (two boxes and a ball: physical volumes 1 to 3,
physical surfaces 11 to 14) with two node sets: 7, the nodes on the side x = 0, and 8, those on the
box interface z = 0.5. It goes .vtu -> .exo, .exo -> .exo (template at 1 and 2 threads, and
Delaunay), .msh -> .exo and .exo -> .msh. Every Exodus output, read by IOSS, must have:
- one element block per physical volume with its volume, and each side set's area and vector
  area equal to its physical surface's (so the side numbering and the orientation agree with
  IOSS's);
- each node set exactly the output nodes on its plane (a node set off its plane, or a node on the
  plane missing from it, fails);
- the names of the Gmsh physical groups, kept from .msh to .exo and back to .msh.
meshio (with netCDF4) reads them too, with the same points, tets and node sets. Bad Exodus inputs
(a hexahedron block, a file that is not Exodus) get one-line errors."""
import argparse
import os
import shutil
import subprocess
import sys

import meshio
import numpy
from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet, vtkUnstructuredGrid
from vtkmodules.vtkCommonDataModel import vtkCellArray, VTK_HEXAHEDRON
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkIOExodus import vtkExodusIIWriter
from vtkmodules.vtkIOIOSS import vtkIOSSReader
from vtkmodules.util.numpy_support import vtk_to_numpy

import TestTaggedTriangles as tagged
from TestCommandLine import digest, run

FAILURES = tagged.FAILURES
check = tagged.check

# Node set id -> (coordinate axis, value): the plane its nodes lie on.
NODE_SETS = {7: (0, 0.0), 8: (2, 0.5)}


def read_exodus(path):
    """(meshio mesh with a Tag cell array and one point array per node set, {(dim, id): name}),
    as ParaView's IOSS reader sees the file. Points are numbered by their Exodus node ids."""
    reader = vtkIOSSReader()
    reader.SetFileName(path)
    reader.UpdateInformation()
    reader.GetSideSetSelection().EnableAllArrays()
    reader.GetNodeSetSelection().EnableAllArrays()
    reader.Update()
    collection = reader.GetOutputDataObject(0)
    entities = []
    points = {}
    for index in range(collection.GetNumberOfPartitionedDataSets()):
        name = collection.GetMetaData(index).Get(vtkCompositeDataSet.NAME())
        part = collection.GetPartitionedDataSet(index).GetPartition(0)
        ids = vtk_to_numpy(part.GetPointData().GetArray("ids")).astype(int) - 1
        coordinates = vtk_to_numpy(part.GetPoints().GetData())
        points.update(zip(ids, coordinates))
        connectivity = vtk_to_numpy(part.GetCells().GetConnectivityArray()).astype(int)
        cell_data = part.GetCellData()
        kind = ("side set" if cell_data.GetArray("element_side") is not None
                else "element block" if part.GetNumberOfCells() and part.GetCellType(0) == 10
                else "node set")
        object_id = vtk_to_numpy(cell_data.GetArray("object_id")) if cell_data.GetArray(
            "object_id") is not None else None
        entities.append((kind, name, ids, connectivity, object_id))
    mesh_points = numpy.array([points[k] for k in range(len(points))])
    cells, tags, node_sets, names = {"tetra": [], "triangle": []}, {"tetra": [], "triangle": []}, \
        {}, {}
    for kind, name, ids, connectivity, object_id in entities:
        if kind == "node set":
            flags = numpy.zeros(len(mesh_points), dtype=int)
            flags[ids] = 1
            # IOSS gives names in lower case.
            node_sets[name[len("nodeset"):] if name.startswith("nodeset") else name] = flags
            continue
        cell_type, corners = ("tetra", 4) if kind == "element block" else ("triangle", 3)
        cells[cell_type].append(ids[connectivity.reshape(-1, corners)])
        tags[cell_type].append(object_id)
        names[(3 if cell_type == "tetra" else 2, int(object_id[0]))] = name
    blocks = [(t, numpy.concatenate(cells[t])) for t in ("tetra", "triangle") if cells[t]]
    mesh = meshio.Mesh(mesh_points, blocks,
                       cell_data={"Tag": [numpy.concatenate(tags[t]) for t, _ in blocks]},
                              point_data={"NodeSet%s" % k: v for k, v in node_sets.items()})
    return mesh, names


def check_meshio_reads(path, expected, description):
    """meshio (with netCDF4) reads the file too: the same points, tets and node sets as IOSS (it
    reads no side sets)."""
    mesh = meshio.read(path)
    tets = sum(len(block.data) for block in mesh.cells if block.type == "tetra")
    expected_tets = sum(len(block.data) for block in expected.cells if block.type == "tetra")
    check(len(mesh.points) == len(expected.points) and tets == expected_tets,
          "%s: meshio reads %d points and %d tets, IOSS %d and %d"
          % (description, len(mesh.points), tets, len(expected.points), expected_tets))
    for set_id in NODE_SETS:
        flags = expected.point_data.get("NodeSet%d" % set_id)
        members = mesh.point_sets.get("NodeSet%d" % set_id)
        check(flags is not None and members is not None and
              sorted(numpy.asarray(members).tolist()) == numpy.flatnonzero(flags).tolist(),
              "%s: meshio's node set %d differs from IOSS's" % (description, set_id))


def check_node_sets(mesh, description):
    """Each node set is exactly the nodes on its plane."""
    for set_id, (axis, value) in NODE_SETS.items():
        flags = mesh.point_data.get("NodeSet%d" % set_id)
        check(flags is not None, "%s: node set %d lost" % (description, set_id))
        if flags is None:
            continue
        on_plane = mesh.points[:, axis] == value
        check(numpy.sum(flags) > 0 and numpy.array_equal(flags.astype(bool), on_plane),
              "%s: node set %d has %d nodes, %d off its plane; %d nodes on the plane are missing"
              % (description, set_id, numpy.sum(flags), numpy.sum(flags.astype(bool) & ~on_plane),
                 numpy.sum(on_plane & ~flags.astype(bool))))


def make_input(scratch, mesh):
    """The Gmsh mesh as .vtu with the two node sets as NodeSet<id> point arrays."""
    point_data = {"NodeSet%d" % k: (mesh.points[:, axis] == value).astype(numpy.int32)
                  for k, (axis, value) in NODE_SETS.items()}
    with_sets = meshio.Mesh(mesh.points, mesh.cells, cell_data=mesh.cell_data,
                            point_data=point_data)
    path = os.path.join(scratch, "two-volumes-node-sets.vtu")
    with_sets.write(path)
    return path, with_sets


def test_round_trips(cgmesh, scratch, source, mesh):
    first = os.path.join(scratch, "first.exo")
    result = run(cgmesh, "refine", source, first, "--partitions", "8")
    check(result.returncode == 0, ".vtu to .exo: " + result.stderr)
    if result.returncode != 0:
        return
    read, _ = read_exodus(first)
    tagged.compare(mesh, read, ".vtu to .exo")
    check_node_sets(read, ".vtu to .exo")
    check_meshio_reads(first, read, ".vtu to .exo")

    cases = {"template": ["--iterations", "2"],
             "delaunay": ["--method", "delaunay", "--volume-factor", "0.3"]}
    for description, options in cases.items():
        digests = set()
        for threads in ("1", "2"):
            output = os.path.join(scratch, "second-%s-%s.exo" % (description, threads))
            result = run(cgmesh, "refine", first, output, "--partitions", "8", "--threads",
                         threads, *options)
            check(result.returncode == 0, ".exo to .exo, %s: %s" % (description, result.stderr))
            if result.returncode != 0:
                continue
            digests.add(digest(output))
            if threads == "2":
                label = ".exo to .exo, " + description
                read, _ = read_exodus(output)
                tagged.compare(mesh, read, label)
                check_node_sets(read, label)
                check_meshio_reads(output, read, label)
                checked = run(cgmesh, "check", output, "--region-array", "Tag")
                check(checked.returncode == 0, label + ": cgmesh check: " + checked.stdout)
        check(len(digests) == 1, ".exo to .exo, %s: 1 and 2 threads wrote different files"
              % description)


def test_names(cgmesh, scratch, mesh):
    """Gmsh's physical names go to Exodus block and side set names, and back."""
    msh = os.path.join(scratch, "two-volumes.msh")
    exo = os.path.join(scratch, "named.exo")
    result = run(cgmesh, "refine", msh, exo, "--partitions", "8")
    check(result.returncode == 0, ".msh to .exo: " + result.stderr)
    if result.returncode != 0:
        return
    read, names = read_exodus(exo)
    tagged.compare(mesh, read, ".msh to .exo")
    # The surface "ball" is renamed: IOSS keys entities by name, and misreads a side set named
    # like a block.
    expected = {(3, 1): "lower", (3, 2): "upper", (3, 3): "ball", (2, 11): "bottom",
                (2, 12): "interface", (2, 13): "ball_surface", (2, 14): "top"}
    check(names == expected, ".msh to .exo: names %s, expected %s" % (names, expected))
    back = os.path.join(scratch, "named.msh")
    result = run(cgmesh, "refine", exo, back, "--partitions", "8")
    check(result.returncode == 0, ".exo to .msh: " + result.stderr)
    if result.returncode != 0:
        return
    tagged.compare(mesh, meshio.read(back), ".exo to .msh", "gmsh:physical")
    with open(back) as handle:
        text = handle.read()
    for (dimension, tag), name in expected.items():
        check('%d %d "%s"' % (dimension, tag, name) in text,
              ".exo to .msh: physical group %d %d %s lost" % (dimension, tag, name))


def write_hexahedron(path):
    """An Exodus file holding one hexahedron, written by VTK's Exodus writer."""
    points = vtkPoints()
    for corner in [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1),
                   (0, 1, 1)]:
        points.InsertNextPoint(*corner)
    grid = vtkUnstructuredGrid()
    grid.SetPoints(points)
    grid.InsertNextCell(VTK_HEXAHEDRON, 8, list(range(8)))
    writer = vtkExodusIIWriter()
    writer.SetFileName(path)
    writer.SetInputData(grid)
    writer.WriteAllTimeStepsOff()
    writer.Write()


def test_errors(cgmesh, scratch):
    hexahedron = os.path.join(scratch, "hexahedron.exo")
    write_hexahedron(hexahedron)
    output = os.path.join(scratch, "hexahedron-refined.exo")
    result = run(cgmesh, "refine", hexahedron, output)
    check(result.returncode == 1 and "HEX" in result.stderr and "linear tetrahedra" in
          result.stderr and len(result.stderr.strip().splitlines()) == 1,
          "hexahedron block: " + result.stderr)
    check(not os.path.exists(output), "hexahedron block: an output was written")
    text = os.path.join(scratch, "text.exo")
    with open(text, "w") as handle:
        handle.write("not a mesh\n")
    result = run(cgmesh, "refine", text, output)
    check(result.returncode == 1 and "not an Exodus II file" in result.stderr,
          "a text file: " + result.stderr)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cgmesh", required=True)
    parser.add_argument("--gmsh", default="gmsh")
    parser.add_argument("--scratch", required=True)
    options = parser.parse_args()
    shutil.rmtree(options.scratch, ignore_errors=True)
    os.makedirs(options.scratch)
    _, mesh = tagged.make_input(options.gmsh, options.scratch)
    if not FAILURES:
        source, with_sets = make_input(options.scratch, mesh)
        test_round_trips(options.cgmesh, options.scratch, source, with_sets)
        test_names(options.cgmesh, options.scratch, mesh)
        test_errors(options.cgmesh, options.scratch)
    if FAILURES:
        print("%d checks failed" % len(FAILURES), file=sys.stderr)
        return 1
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
