"""Mixed tetrahedra and triangles through `cgmesh refine`, and the Gmsh, Medit and TetGen file
formats. First on a mesh Gmsh makes: two stacked boxes
and a ball inside the lower one (three physical volumes), with physical surfaces on the bottom,
the top, the box interface and the ball's curved surface, converted to .vtu by meshio as a Gmsh
user would. Both methods, with and without a region array: the output, read back by meshio, must
keep every tag, with each planar surface's nodes exactly the nodes on its plane (node sets
exact); each tag's triangles must cover the same surface (area and vector area conserved,
so the orientation is kept too) with more triangles than before; every triangle must be a boundary
or material-interface face of the output tets; every physical volume keeps its volume; 1 and 2
threads write the same bytes; and the input errors name the offending cells. The same mesh then
goes .msh to .msh (4.1 and 2.2) and to Medit .mesh, and a TetGen mesh with region attributes and
facet markers goes .ele to .ele, each output read back by meshio (or the test's TetGen reader) for
the same checks and by Gmsh or TetGen themselves."""
import argparse
import os
import re
import shutil
import subprocess
import sys

import meshio
import numpy

from TestCommandLine import digest, region_volumes, run

FAILURES = []

GEOMETRY = """SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 0.5};
Box(2) = {0, 0, 0.5, 1, 1, 0.5};
Sphere(3) = {0.5, 0.5, 0.25, 0.15};
BooleanFragments{ Volume{1, 2, 3}; Delete; }{}
e = 1e-3;
ball() = Volume In BoundingBox{0.35 - e, 0.35 - e, 0.1 - e, 0.65 + e, 0.65 + e, 0.4 + e};
lower() = Volume In BoundingBox{-e, -e, -e, 1 + e, 1 + e, 0.5 + e};
Physical Volume("lower", 1) = {lower()};
Physical Volume("lower", 1) -= {ball()};
Physical Volume("upper", 2) = Volume In BoundingBox{-e, -e, 0.5 - e, 1 + e, 1 + e, 1 + e};
Physical Volume("ball", 3) = {ball()};
Physical Surface("bottom", 11) = Surface In BoundingBox{-e, -e, -e, 1 + e, 1 + e, e};
Physical Surface("interface", 12) = Surface In BoundingBox{-e, -e, 0.5 - e, 1 + e, 1 + e, 0.5 + e};
Physical Surface("ball", 13) = Surface In BoundingBox{0.35 - e, 0.35 - e, 0.1 - e, 0.65 + e, 0.65 + e, 0.4 + e};
Physical Surface("top", 14) = Surface In BoundingBox{-e, -e, 1 - e, 1 + e, 1 + e, 1 + e};
Mesh.MeshSizeMax = 0.12;
"""


def check(condition, message):
    if not condition:
        FAILURES.append(message)
        print("check failed: " + message, file=sys.stderr)


def cells_of(mesh, cell_type, array="Tag"):
    """(connectivity, `array` values) of every block of `cell_type`, joined."""
    blocks = [(block.data, tags) for block, tags in zip(mesh.cells, mesh.cell_data[array])
              if block.type == cell_type]
    if not blocks:
        return numpy.zeros((0, 4 if cell_type == "tetra" else 3), dtype=int), numpy.zeros(0)
    return (numpy.concatenate([b[0] for b in blocks]),
            numpy.concatenate([numpy.asarray(b[1]).ravel() for b in blocks]))


def surface_figures(mesh, array):
    """{tag: (triangle count, area, vector area)} of the triangles."""
    triangles, tags = cells_of(mesh, "triangle", array)
    p = mesh.points[triangles]
    normals = 0.5 * numpy.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    areas = numpy.linalg.norm(normals, axis=1)
    return {int(tag): (int(numpy.sum(tags == tag)), float(areas[tags == tag].sum()),
                       normals[tags == tag].sum(axis=0)) for tag in numpy.unique(tags)}


def volume_figures(mesh, array):
    """{tag: volume} of the tets."""
    tets, tags = cells_of(mesh, "tetra", array)
    p = mesh.points[tets]
    volumes = numpy.abs(numpy.einsum("ij,ij->i", p[:, 1] - p[:, 0],
                                     numpy.cross(p[:, 2] - p[:, 0], p[:, 3] - p[:, 0]))) / 6
    return {int(tag): float(volumes[tags == tag].sum()) for tag in numpy.unique(tags)}


def tets_of_faces(tets):
    """{sorted face corners: indices of the tets holding the face}."""
    holders = {}
    for index, tet in enumerate(tets):
        for skip in range(4):
            face = tuple(sorted(int(tet[k]) for k in range(4) if k != skip))
            holders.setdefault(face, []).append(index)
    return holders


def triangles_are_kept_faces(mesh, array):
    """How many triangles are no face of a tet, or lie between two tets of one tag."""
    tets, tet_tags = cells_of(mesh, "tetra", array)
    holders = tets_of_faces(tets)
    triangles, _ = cells_of(mesh, "triangle", array)
    bad = 0
    for triangle in triangles:
        tags = [tet_tags[t] for t in holders.get(tuple(sorted(int(v) for v in triangle)), [])]
        bad += not (len(tags) == 1 or (len(tags) == 2 and tags[0] != tags[1]))
    return bad


def compare(before, after, description, array="Tag"):
    """Tags, areas, vector areas and volumes of `after` (tags in `array`) against `before`."""
    surfaces_before, surfaces_after = surface_figures(before, "Tag"), surface_figures(after, array)
    check(sorted(surfaces_before) == sorted(surfaces_after),
          "%s: surface tags %s, expected %s" % (description, sorted(surfaces_after),
                                                sorted(surfaces_before)))
    for tag, (count, area, vector) in surfaces_before.items():
        if tag not in surfaces_after:
            continue
        count_after, area_after, vector_after = surfaces_after[tag]
        check(count_after > count, "%s: tag %d has %d triangles, %d before: not refined"
              % (description, tag, count_after, count))
        check(abs(area_after - area) <= 1e-12 * area,
              "%s: tag %d area %.15g, expected %.15g" % (description, tag, area_after, area))
        check(numpy.linalg.norm(vector_after - vector) <= 1e-12 * area,
              "%s: tag %d vector area %s, expected %s (orientation)"
              % (description, tag, vector_after, vector))
    volumes_before, volumes_after = volume_figures(before, "Tag"), volume_figures(after, array)
    check(sorted(volumes_before) == sorted(volumes_after),
          "%s: volume tags %s" % (description, sorted(volumes_after)))
    for tag, volume in volumes_before.items():
        check(abs(volumes_after.get(tag, 0) - volume) <= 1e-12 * volume,
              "%s: volume of tag %d is %.15g, expected %.15g"
              % (description, tag, volumes_after.get(tag, 0), volume))
    bad = triangles_are_kept_faces(after, array)
    check(bad == 0, "%s: %d triangles are no boundary or interface face" % (description, bad))


# Physical surfaces on planes: (axis, value) by tag.
PLANE_SURFACES = {11: (2, 0.0), 12: (2, 0.5), 14: (2, 1.0)}


def check_node_sets(after, array, description):
    """The nodes of each planar physical surface (its node set, as Gmsh takes a physical group's
    nodes) are exactly the output nodes on its plane: none off it, none on it missing."""
    triangles, tags = cells_of(after, "triangle", array)
    for tag, (axis, value) in PLANE_SURFACES.items():
        nodes = set(numpy.unique(triangles[tags == tag]).tolist())
        on_plane = set(numpy.flatnonzero(after.points[:, axis] == value).tolist())
        check(nodes and nodes == on_plane,
              "%s: node set of tag %d has %d nodes, %d off its plane, %d on it missing"
              % (description, tag, len(nodes), len(nodes - on_plane), len(on_plane - nodes)))


def test_file_formats(cgmesh, gmsh, scratch, mesh):
    """Gmsh .msh in, .msh 4.1 and 2.2 and Medit .mesh out: the tags, areas and volumes as through
    .vtu, the physical names kept, and Gmsh itself reads every output back."""
    msh = os.path.join(scratch, "two-volumes.msh")
    # Delaunay from a .msh: TetGen runs in a process that has loaded Gmsh's library, which carries
    # a TetGen of its own.
    outputs = {"msh 4.1": ("refined.msh", [], "gmsh:physical"),
               "msh delaunay": ("refined-delaunay.msh", ["--method", "delaunay", "--volume-factor",
                                                         "0.3"], "gmsh:physical"),
               "msh 2.2": ("refined-2.2.msh", ["--msh-version", "2.2"], "gmsh:physical"),
               "medit": ("refined.mesh", [], "medit:ref")}
    for description, (name, options, array) in outputs.items():
        output = os.path.join(scratch, name)
        iterations = [] if "delaunay" in options else ["--iterations", "2"]
        result = run(cgmesh, "refine", msh, output, "--partitions", "8", *iterations, *options)
        check(result.returncode == 0, "%s: %s" % (description, result.stderr))
        if result.returncode != 0:
            continue
        refined = meshio.read(output)
        compare(mesh, refined, description, array)
        check_node_sets(refined, array, description)
        if name.endswith(".mesh"):
            # Vertex references are the nodes' entities, as Gmsh writes them: surface nodes
            # carry their surface's, the others their volume's.
            references = numpy.asarray(refined.point_data["medit:ref"])
            triangles, _ = cells_of(refined, "triangle", array)
            on_surfaces = numpy.zeros(len(references), dtype=bool)
            on_surfaces[numpy.unique(triangles)] = True
            surface_refs = set(references[on_surfaces].tolist())
            volume_refs = set(references[~on_surfaces].tolist())
            check(len(surface_refs) > 1 and len(volume_refs) > 1 and
                  not surface_refs & volume_refs,
                  "medit: vertex references %s on surfaces, %s elsewhere"
                  % (sorted(surface_refs), sorted(volume_refs)))
        if name.endswith(".msh"):
            with open(output) as handle:
                text = handle.read()
            check(("$MeshFormat\n%s " % ("2.2" if "2.2" in options else "4.1")) in text,
                  "%s: the file is not in that format" % description)
            for group in ('2 11 "bottom"', '2 13 "ball"', '3 1 "lower"', '3 3 "ball"'):
                check(group in text, "%s: physical group %s lost" % (description, group))
        reread = os.path.join(scratch, "reread-" + name + ".msh")
        result = subprocess.run([gmsh, output, "-0", "-o", reread], capture_output=True,
                                text=True)
        check(result.returncode == 0 and "Error" not in result.stdout,
              "%s: Gmsh does not read the output: %s" % (description, result.stdout[-1500:]))
    # Nothing to split: the tets alone decide, the tagged triangles do not hide the warning.
    result = run(cgmesh, "refine", msh, os.path.join(scratch, "unrefined.msh"),
                 "--max-edge-length", "100")
    check(result.returncode == 0 and "cgmesh: warning: nothing was refined: no edge is longer "
          "than the threshold 100" in result.stderr and "nothing-refined 1" in result.stdout,
          "tagged triangles, nothing refined: %r" % result.stderr)
    result = run(cgmesh, "refine", msh, os.path.join(scratch, "bad.vtu"), "--msh-version", "2.2")
    check(result.returncode == 2 and "needs a .msh output" in result.stderr,
          "--msh-version for a .vtu output accepted: " + result.stderr)
    result = run(cgmesh, "refine", msh, os.path.join(scratch, "bad.msh"), "--msh-version", "3")
    check(result.returncode != 0 and "--msh-version" in result.stderr,
          "--msh-version 3 accepted: " + result.stderr)
    result = run(cgmesh, "refine", msh, os.path.join(scratch, "bad.msh"), "--compression", "zlib")
    check(result.returncode != 0 and "needs a .vtu output" in result.stderr,
          "--compression for a .msh output accepted: " + result.stderr)


# A box split at z = 0.5 into two regions (attributes 1 and 2), facet markers 11 (bottom),
# 12 (the splitting facet), 13 (top) and 14 (the sides).
TETGEN_POLY = """12 3 0 0
1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0
5 0 0 0.5\n6 1 0 0.5\n7 1 1 0.5\n8 0 1 0.5
9 0 0 1\n10 1 0 1\n11 1 1 1\n12 0 1 1
11 1
1 0 11\n4 1 2 3 4
1 0 12\n4 5 6 7 8
1 0 13\n4 9 10 11 12
1 0 14\n4 1 2 6 5\n1 0 14\n4 2 3 7 6\n1 0 14\n4 3 4 8 7\n1 0 14\n4 4 1 5 8
1 0 14\n4 5 6 10 9\n1 0 14\n4 6 7 11 10\n1 0 14\n4 7 8 12 11\n1 0 14\n4 8 5 9 12
0
2
1 0.5 0.5 0.25 1 0
2 0.5 0.5 0.75 2 0
"""


def read_tetgen(base):
    """A meshio mesh with a Tag cell array from TetGen's .node, .ele and .face files (a test's own
    reader: meshio reads no .face files)."""
    def rows(extension):
        with open(base + extension) as handle:
            lines = [line.split("#")[0].split() for line in handle]
        lines = [line for line in lines if line]
        return lines[0], lines[1:]
    header, nodes = rows(".node")
    first = int(nodes[0][0])
    points = numpy.array([[float(v) for v in row[1:4]] for row in nodes])
    header, elements = rows(".ele")
    tets = numpy.array([[int(v) - first for v in row[1:5]] for row in elements])
    tet_tags = numpy.array([int(float(row[5])) if len(row) > 5 else 0 for row in elements])
    header, faces = rows(".face")
    triangles = numpy.array([[int(v) - first for v in row[1:4]] for row in faces])
    triangle_tags = numpy.array([int(row[4]) if len(row) > 4 else 0 for row in faces])
    return meshio.Mesh(points, [("tetra", tets), ("triangle", triangles)],
                       cell_data={"Tag": [tet_tags, triangle_tags]})


def test_tetgen_files(cgmesh, tetgen, scratch):
    """A TetGen mesh with region attributes and facet markers, refined from .ele to .ele: each
    marker's area and each region's volume conserved, and TetGen reads the output back."""
    poly = os.path.join(scratch, "split-box.poly")
    with open(poly, "w") as handle:
        handle.write(TETGEN_POLY)
    result = subprocess.run([tetgen, "-pqAa0.002", poly], capture_output=True, text=True)
    check(result.returncode == 0, "tetgen: " + result.stdout[-1500:])
    if result.returncode != 0:
        return
    source = os.path.join(scratch, "split-box.1.ele")
    output = os.path.join(scratch, "split-box-refined.ele")
    result = run(cgmesh, "refine", source, output, "--partitions", "8")
    check(result.returncode == 0, "refine .ele: " + result.stderr)
    if result.returncode != 0:
        return
    # The .node name of the input is the same mesh: refused before anything is written.
    with open(source) as handle:
        elements = handle.read()
    result = run(cgmesh, "refine", source, source[:-4] + ".node")
    check(result.returncode != 0 and "would overwrite IN" in result.stderr,
          "refine a.ele a.node accepted: " + result.stderr)
    with open(source) as handle:
        check(handle.read() == elements, "refine a.ele a.node changed the input")
    before = read_tetgen(source[:-4])
    compare(before, read_tetgen(output[:-4]), "tetgen files")
    check(sorted(volume_figures(before, "Tag")) == [1, 2],
          "tetgen files: regions %s" % sorted(volume_figures(before, "Tag")))
    result = subprocess.run([tetgen, "-rNEF", output[:-4]], capture_output=True, text=True)
    check(result.returncode == 0 and "Error" not in result.stdout,
          "TetGen does not read the output: " + result.stdout[-1500:])
    # Malformed files: one line of error each (TetGen's own reader would crash on them).
    nodes = "5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n"
    bad_files = {
        "empty": ("", "", "not a TetGen file"),
        "garbage": (nodes, "tetrahedra follow\n", "not a TetGen file"),
        "short": (nodes, "2 4 0\n1 1 2 3 4\n", "record 2 of the 2 its header announces is "
                  "missing"),
        "incomplete": (nodes, "1 4 0\n1 1 2 3\n", "record 1 of the 1 its header announces "
                       "is incomplete"),
        "out-of-range": (nodes, "1 4 0\n1 1 2 3 17\n", "TetGen cannot read"),
        "not-a-number": (nodes.replace("5 1 1 1", "5 nan 1 1"), "1 4 0\n1 1 2 3 4\n",
                         "TetGen cannot read"),
    }
    for description, (node_text, ele_text, expected) in bad_files.items():
        base = os.path.join(scratch, "bad-" + description)
        for extension, text in ((".node", node_text), (".ele", ele_text)):
            with open(base + extension, "w") as handle:
                handle.write(text)
        bad_output = os.path.join(scratch, "bad-%s-refined.vtu" % description)
        result = run(cgmesh, "refine", base + ".ele", bad_output)
        check(result.returncode == 1 and expected in result.stderr and
              not os.path.exists(bad_output),
              "malformed TetGen files (%s): exit %d, %r" % (description, result.returncode,
                                                          result.stderr))


def make_point_cloud(tetgen, scratch, count, seed):
    """TetGen's tetrahedralisation of `count` random points in the unit cube (numpy's
    default_rng(seed)), with its hull faces tagged and its hull points marked 1 (node markers,
    read as the point label `Marker`): the base name of its .1.node/.1.ele/.1.face files, or None
    if TetGen failed."""
    points = numpy.random.default_rng(seed).random((count, 3))
    base = os.path.join(scratch, "cloud-%d-%d" % (count, seed))
    with open(base + ".node", "w") as handle:
        handle.write("%d 3 0 0\n" % len(points))
        for index, point in enumerate(points):
            handle.write("%d %.17g %.17g %.17g\n" % (index + 1, *point))
    result = subprocess.run([tetgen, "-Q", base + ".node"], capture_output=True, text=True)
    check(result.returncode == 0, "tetgen: " + result.stdout[-1500:])
    if result.returncode != 0:
        return None
    hull = set(int(v) for row in open(base + ".1.face").read().split("\n")[1:]
               for v in row.split("#")[0].split()[1:4])
    with open(base + ".1.node") as handle:
        rows = [row.split() for row in handle if row.split() and not row.startswith("#")]
    with open(base + ".1.node", "w") as handle:
        handle.write("%s 3 0 1\n" % rows[0][0])
        for row in rows[1:]:
            handle.write("%s %s %s %s %d\n" % (*row[:4], int(row[0]) in hull))
    return base


def unmarked_hull_points(refined):
    """Points of the refined cloud's tagged (hull) triangles whose `Marker` is not 1."""
    triangles, _ = cells_of(refined, "triangle", "Tag")
    return int(numpy.sum(refined.point_data["Marker"][numpy.unique(triangles)] != 1))


def test_random_point_cloud_delaunay(cgmesh, tetgen, scratch):
    """TetGen's tetrahedralisation of 2,000 random points (slivers up to its flat hull patches),
    its hull faces tagged and its hull points marked, refined by the Delaunay method: meshed anew
    first, the hull's triangles split and merged; valid (no flat tet, which TetGen can leave on
    four coplanar hull points when it meshes a partition anew), the tagged area the input's,
    every tagged triangle on the boundary and every point of one marked (points TetGen put on
    the hull weigh its face's corners alone), the same for 1 and 2 threads."""
    base = make_point_cloud(tetgen, scratch, 2000, 4)
    if base is None:
        return
    digests = set()
    for threads in ("1", "2"):
        output = os.path.join(scratch, "cloud-delaunay-%s.vtu" % threads)
        result = run(cgmesh, "refine", base + ".1.ele", output, "--method", "delaunay",
                     "--threads", threads)
        check(result.returncode == 0, "random cloud, Delaunay: " + result.stderr)
        if result.returncode != 0:
            return
        digests.add(digest(output))
    checked = run(cgmesh, "check", output)
    check(checked.returncode == 0 and checked.stdout.rstrip().endswith("valid"),
          "random cloud, Delaunay: cgmesh check: " + checked.stdout[-800:])
    refined = meshio.read(output)
    check(triangles_are_kept_faces(refined, "Tag") == 0,
          "random cloud, Delaunay: tagged triangles inside the mesh")
    (area_before, area_after) = (sum(figures[1] for figures in surface_figures(mesh, "Tag").values())
                                 for mesh in (read_tetgen(base + ".1"), refined))
    check(abs(area_after - area_before) <= 1e-12 * area_before,
          "random cloud, Delaunay: tagged area %.15g, input %.15g" % (area_after, area_before))
    unmarked = unmarked_hull_points(refined)
    check(unmarked == 0, "random cloud, Delaunay: %d hull points lost their marker" % unmarked)
    check(len(digests) == 1, "random cloud, Delaunay: 1 and 2 threads wrote different files")


def test_hull_markers_of_moved_neighbours(cgmesh, tetgen, scratch):
    """The tetrahedralisation of 4,000 random points (default_rng(1)), refined by the Delaunay
    method: TetGen puts points on hull edges and faces whose weights carry rounding noise on
    interior corners that improvement moved. Such a point must keep its weights (and the marker
    its face's corners share) rather than be located anew in the input, where the noise on the
    located tet's interior corner exceeded the negligible and 3 of the 20,215 hull points lost
    their marker."""
    base = make_point_cloud(tetgen, scratch, 4000, 1)
    if base is None:
        return
    output = os.path.join(scratch, "cloud-4000-delaunay.vtu")
    result = run(cgmesh, "refine", base + ".1.ele", output, "--method", "delaunay")
    check(result.returncode == 0, "4,000-point cloud, Delaunay: " + result.stderr)
    if result.returncode != 0:
        return
    unmarked = unmarked_hull_points(meshio.read(output))
    check(unmarked == 0, "4,000-point cloud, Delaunay: %d hull points lost their marker" % unmarked)


def make_input(gmsh, scratch):
    """The Gmsh mesh as a Gmsh user converts it: tets and triangles with their physical tags."""
    geometry = os.path.join(scratch, "two-volumes.geo")
    with open(geometry, "w") as handle:
        handle.write(GEOMETRY)
    msh = os.path.join(scratch, "two-volumes.msh")
    result = subprocess.run([gmsh, geometry, "-3", "-o", msh], capture_output=True, text=True)
    check(result.returncode == 0, "gmsh: " + result.stdout[-2000:])
    source = meshio.read(msh)
    blocks, tags = [], []
    for block, physical in zip(source.cells, source.cell_data["gmsh:physical"]):
        if block.type in ("tetra", "triangle"):
            blocks.append(block)
            tags.append(physical)
    mesh = meshio.Mesh(source.points, blocks, cell_data={"Tag": tags})
    path = os.path.join(scratch, "two-volumes.vtu")
    mesh.write(path)
    return path, mesh


def test_refinement(cgmesh, scratch, path, mesh):
    cases = {
        "template, region array": ["--region-array", "Tag", "--iterations", "2"],
        "template, default labels": ["--iterations", "2"],
        "delaunay": ["--region-array", "Tag", "--method", "delaunay", "--volume-factor", "0.3"],
    }
    for description, options in cases.items():
        digests = set()
        for threads in ("1", "2"):
            output = os.path.join(scratch, "refined-%s-%s.vtu"
                                  % (description.replace(" ", "").replace(",", "-"), threads))
            result = run(cgmesh, "refine", path, output, "--partitions", "8", "--threads",
                         threads, "--compression", "zlib", *options)
            check(result.returncode == 0, "%s: %s" % (description, result.stderr))
            if result.returncode != 0:
                continue
            digests.add(digest(output))
            checked = run(cgmesh, "check", output, "--region-array", "Tag")
            check(checked.returncode == 0 and
                  re.search(r"^triangles on no tet face +0$", checked.stdout, re.MULTILINE),
                  "%s: cgmesh check: %s" % (description, checked.stdout[-1500:]))
            if threads == "2":
                refined = meshio.read(output)
                compare(mesh, refined, description)
                check_node_sets(refined, "Tag", description)
        check(len(digests) == 1, "%s: 1 and 2 threads wrote different files" % description)
    volumes, status = region_volumes(cgmesh, path, "Tag")
    check(status == 0 and sorted(volumes) == [1, 2, 3], "input check: %s %d" % (volumes, status))


def expect_error(cgmesh, scratch, mesh, description, texts):
    """`cgmesh refine` of `mesh` fails with one line naming `texts`, and writes nothing."""
    path = os.path.join(scratch, "bad-%s.vtu" % description)
    mesh.write(path)
    output = os.path.join(scratch, "bad-%s-refined.vtu" % description)
    result = run(cgmesh, "refine", path, output)
    check(result.returncode != 0, "%s: refine succeeded" % description)
    for text in texts:
        check(text in result.stderr, "%s: the error does not say %r: %s"
              % (description, text, result.stderr))
    check(not os.path.exists(output), "%s: an output was written" % description)


def test_errors(cgmesh, scratch, mesh):
    tets, tet_tags = cells_of(mesh, "tetra")
    triangles, triangle_tags = cells_of(mesh, "triangle")
    # A triangle across a tet (three corners of two different tets): no face.
    stray = numpy.array([[tets[0][0], tets[0][1], tets[500][2]]])
    broken = meshio.Mesh(mesh.points, [("tetra", tets), ("triangle", numpy.vstack([triangles,
                                                                                    stray]))],
                         cell_data={"Tag": [tet_tags, numpy.append(triangle_tags, 99)]})
    stray_cell = len(tets) + len(triangles)
    expect_error(cgmesh, scratch, broken, "stray-triangle",
                 ["1 of the input's %d triangles are not faces" % (len(triangles) + 1),
                  "cell %d" % stray_cell])
    # An interior face of the upper box: between two tets of one material.
    inner = next(face for face, held in tets_of_faces(tets).items()
                 if len(held) == 2 and tet_tags[held[0]] == tet_tags[held[1]] == 2)
    inside = meshio.Mesh(mesh.points, [("tetra", tets), ("triangle", numpy.vstack([triangles,
                                                                                   [inner]]))],
                         cell_data={"Tag": [tet_tags, numpy.append(triangle_tags, 98)]})
    expect_error(cgmesh, scratch, inside, "inner-triangle",
                 ["lie between two tetrahedra of the same material", "cell %d" % stray_cell])
    # From a Gmsh file the same error names the file's element and node numbers.
    path = os.path.join(scratch, "bad-inner-triangle.msh")
    tags = [numpy.asarray(tet_tags), numpy.append(triangle_tags, 98)]
    meshio.write(path, meshio.Mesh(mesh.points, inside.cells,
                                   cell_data={"gmsh:physical": tags, "gmsh:geometrical": tags}),
                 file_format="gmsh22", binary=False)
    nodes = sorted(int(v) + 1 for v in inner)  # meshio numbers the nodes from 1, in order
    with open(path) as handle:
        text = handle.read()
    rows = text.split("$Elements")[1].split("$EndElements")[0].split("\n")[2:]
    element = next(int(row.split()[0]) for row in rows
                   if row.split() and row.split()[1] == "2" and
                   sorted(int(v) for v in row.split()[3 + int(row.split()[2]):]) == nodes)
    result = run(cgmesh, "refine", path, os.path.join(scratch, "bad-inner-triangle-refined.vtu"))
    named = re.search(r"the first is element (\d+) \(nodes (\d+), (\d+), (\d+)\)",
                      result.stderr)
    check(result.returncode == 1 and named is not None and int(named.group(1)) == element and
          sorted(int(named.group(k)) for k in (2, 3, 4)) == nodes,
          "inner triangle from .msh: expected element %d (nodes %s): %s"
          % (element, nodes, result.stderr))
    lines = meshio.Mesh(mesh.points, [("tetra", tets), ("triangle", triangles),
                                      ("line", numpy.array([[tets[0][0], tets[0][1]]]))],
                        cell_data={"Tag": [tet_tags, triangle_tags, [7]]})
    expect_error(cgmesh, scratch, lines, "line",
                 ["1 Line", "Extract Cells By Type (Tetra, Triangle)"])


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cgmesh", required=True)
    parser.add_argument("--gmsh", default="gmsh")
    parser.add_argument("--tetgen", default="tetgen")
    parser.add_argument("--scratch", required=True)
    options = parser.parse_args()
    shutil.rmtree(options.scratch, ignore_errors=True)
    os.makedirs(options.scratch)
    path, mesh = make_input(options.gmsh, options.scratch)
    if not FAILURES:
        test_refinement(options.cgmesh, options.scratch, path, mesh)
        test_errors(options.cgmesh, options.scratch, mesh)
        test_file_formats(options.cgmesh, options.gmsh, options.scratch, mesh)
        test_tetgen_files(options.cgmesh, options.tetgen, options.scratch)
        test_random_point_cloud_delaunay(options.cgmesh, options.tetgen, options.scratch)
        test_hull_markers_of_moved_neighbours(options.cgmesh, options.tetgen, options.scratch)
    if FAILURES:
        print("%d checks failed" % len(FAILURES), file=sys.stderr)
        return 1
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
