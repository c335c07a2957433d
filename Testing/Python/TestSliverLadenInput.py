"""A sliver-laden input through the command line: a box of two regions that TetGen fills with
pseudo-random points and no quality bound (`tetgen -pAi`), read from its .node and .ele files.
Template refinement meshes it anew first (the table's `input remeshed boxes`, the stats), keeps
both regions' volumes (`cgmesh check`), gives the same file at 1 and 2 threads, and ends far better
shaped than refining it as given. Refined as given (--no-improve-input), it warns and says why.
With its facet markers as tagged triangles (the .face file beside it), both methods mesh it anew
too, and every marker's surface survives."""
import argparse
import json
import os
import random
import shutil
import subprocess
import sys

import TestTaggedTriangles
from TestCommandLine import digest, region_volumes, run
from TestTaggedTriangles import TETGEN_POLY

FAILURES = []


def check(condition, message):
    if not condition:
        FAILURES.append(message)
        print("check failed: " + message, file=sys.stderr)


def make_input(tetgen, scratch):
    """TetGen's sliver-laden mesh of the split box: its base name, or None."""
    base = os.path.join(scratch, "split-box")
    with open(base + ".poly", "w") as handle:
        handle.write(TETGEN_POLY)
    generator = random.Random(7)
    points = [(generator.random(), generator.random(), generator.random()) for _ in range(1500)]
    with open(base + ".a.node", "w") as handle:
        handle.write("%d 3 0 0\n" % len(points))
        for index, point in enumerate(points, 1):
            handle.write("%d %r %r %r\n" % ((index,) + point))
    result = subprocess.run([tetgen, "-pAiQ", base + ".poly"], capture_output=True, text=True)
    check(result.returncode == 0, "tetgen: " + result.stdout[-1500:] + result.stderr[-500:])
    return base + ".1" if result.returncode == 0 else None


def refine(cgmesh, source, output, options, bound=("--edge-length-factor", "0.5")):
    """(stats, stdout, stderr) of a successful run, or None."""
    stats = output + ".json"
    result = run(cgmesh, "refine", source, output, *bound, "--partitions", "16", "--stats", stats,
                 *options)
    check(result.returncode == 0, "refine %s %s: %s" % (source, options, result.stderr))
    if result.returncode != 0:
        return None
    with open(stats) as handle:
        return json.load(handle), result.stdout, result.stderr


def test_meshed_anew(cgmesh, scratch, tagged):
    # The same mesh without its .face file: no tagged triangles, so its boundary may change.
    bare = os.path.join(scratch, "bare")
    for extension in (".node", ".ele"):
        shutil.copyfile(tagged + extension, bare + extension)
    before, status = region_volumes(cgmesh, bare + ".ele", "Tag")
    check(status == 0 and sorted(before) == [1, 2], "the input's regions: %s" % before)

    outputs = []
    for threads in ("1", "2"):
        output = os.path.join(scratch, "anew-%s.vtu" % threads)
        ran = refine(cgmesh, bare + ".ele", output, ["--threads", threads])
        if ran is None:
            return
        stats, table, warnings = ran
        outputs.append(output)
    check("input remeshed boxes    1 (0 failed)" in table, "the table: " + table)
    check(stats["inputRemeshedBoxes"] == 1 and stats["inputRemeshFailures"] == 0,
          "stats: %s remeshed, %s failed" % (stats["inputRemeshedBoxes"],
                                             stats["inputRemeshFailures"]))
    check("sliver-laden" not in warnings, "a warning after meshing anew: " + warnings)
    check(digest(outputs[0]) == digest(outputs[1]), "1 and 2 threads give different files")
    after, status = region_volumes(cgmesh, outputs[1], "Tag")
    check(status == 0, "cgmesh check fails on the output")
    check(sorted(after) == [1, 2] and all(abs(after[r] - before[r]) < 1e-9 for r in before),
          "region volumes %s, input %s" % (after, before))
    anew = stats["quality"]["all"]

    ran = refine(cgmesh, bare + ".ele", os.path.join(scratch, "as-given.vtu"),
                 ["--no-improve-input"])
    if ran is None:
        return
    stats, table, warnings = ran
    check(stats["inputRemeshedBoxes"] == 0, "--no-improve-input meshed the input anew")
    check("sliver-laden-input-kept" in table and "(ImproveInput is off)" in warnings,
          "--no-improve-input: no warning, or not why: " + warnings)
    given = stats["quality"]["all"]
    print("split box with 1,500 random points: min dihedral p1 %.2f degrees refined as given, "
          "%.2f meshed anew first" % (given["minDihedralAngleP1"], anew["minDihedralAngleP1"]))
    check(anew["minDihedralAngleP1"] > 10 and given["minDihedralAngleP1"] < 5,
          "min dihedral p1 %.2f meshed anew, %.2f as given" % (anew["minDihedralAngleP1"],
                                                              given["minDihedralAngleP1"]))


def read_node_markers(base):
    """(coordinates, markers) of TetGen's .node file with a marker column."""
    with open(base + ".node") as handle:
        rows = [line.split("#")[0].split() for line in handle]
    rows = [row for row in rows if row]
    count, markers = int(rows[0][0]), int(rows[0][3])
    check(markers == 1, "%s.node has no marker column" % base)
    points = [[float(v) for v in row[1:4]] for row in rows[1:count + 1]]
    return points, [int(row[4]) if markers else 0 for row in rows[1:count + 1]]


def test_boundary_labels_kept(cgmesh, scratch, tagged):
    """Point labels (TetGen's node markers: 1 on the box's surface) survive meshing anew: every
    output point on the surface has marker 1, those TetGen put there too."""
    marked = os.path.join(scratch, "marked")
    for extension in (".ele", ".face"):
        shutil.copyfile(tagged + extension, marked + extension)
    with open(tagged + ".node") as source, open(marked + ".node", "w") as target:
        rows = [line.split("#")[0].split() for line in source]
        rows = [row for row in rows if row]
        target.write("%s 3 0 1\n" % rows[0][0])
        for row in rows[1:int(rows[0][0]) + 1]:
            on_surface = any(float(v) in (0.0, 1.0) for v in row[1:4])
            target.write("%s %s %s %s %d\n" % (row[0], row[1], row[2], row[3], on_surface))
    for method, bound in (("template", ("--edge-length-factor", "0.5")),
                          ("delaunay", ("--method", "delaunay", "--volume-factor", "0.5"))):
        output = os.path.join(scratch, "marked-%s.ele" % method)
        ran = refine(cgmesh, marked + ".ele", output, ["--threads", "2"], bound)
        if ran is None:
            return
        check(ran[0]["inputRemeshedBoxes"] == 1, "marked, %s: not meshed anew" % method)
        points, markers = read_node_markers(output[:-4])
        lost = sum(1 for point, marker in zip(points, markers)
                   if marker != 1 and any(abs(v) < 1e-12 or abs(v - 1) < 1e-12 for v in point))
        check(lost == 0, "marked, %s: %d points on the surface lost their marker" % (method, lost))


def test_tagged_triangles_meshed_anew(cgmesh, scratch, tagged):
    """With its facet markers as tagged triangles, the input is meshed anew too: each marker's
    faces split and merge only among themselves, and the children are found by position. Each
    marker keeps its area and orientation, each region its volume, every triangle lies on the
    boundary or the interface, the shapes are as good as without tags, and the files are the
    same at 1 and 2 threads."""
    before = TestTaggedTriangles.read_tetgen(tagged)
    outputs = []
    bounds = {"template": ("--edge-length-factor", "0.5"),
              "delaunay": ("--method", "delaunay", "--volume-factor", "0.5")}
    for method in ("template", "delaunay"):
        for threads in ("1", "2"):
            output = os.path.join(scratch, "tagged-%s-%s.ele" % (method, threads))
            ran = refine(cgmesh, tagged + ".ele", output, ["--threads", threads], bounds[method])
            if ran is None:
                return
            stats, table, warnings = ran
            outputs.append(output)
            check(stats["inputRemeshedBoxes"] == 1 and stats["inputRemeshFailures"] == 0,
                  "tagged, %s: %s remeshed, %s failed" % (method, stats["inputRemeshedBoxes"],
                                                          stats["inputRemeshFailures"]))
            check("sliver-laden" not in warnings, "tagged, %s: warned %s" % (method, warnings))
            quality = stats["quality"]["all"]
            check(quality["minDihedralAngleP1"] > 10,
                  "tagged, %s: min dihedral p1 %.2f degrees" % (method,
                                                                quality["minDihedralAngleP1"]))
        for extension in (".node", ".ele", ".face"):
            check(digest(outputs[-2][:-4] + extension) == digest(outputs[-1][:-4] + extension),
                  "tagged, %s: 1 and 2 threads give different %s files" % (method, extension))
        TestTaggedTriangles.compare(before, TestTaggedTriangles.read_tetgen(outputs[-1][:-4]),
                                    "tagged, meshed anew, " + method)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cgmesh", required=True)
    parser.add_argument("--tetgen", required=True)
    parser.add_argument("--scratch", required=True)
    options = parser.parse_args()
    shutil.rmtree(options.scratch, ignore_errors=True)
    os.makedirs(options.scratch)
    tagged = make_input(options.tetgen, options.scratch)
    if tagged is not None:
        test_meshed_anew(options.cgmesh, options.scratch, tagged)
        test_tagged_triangles_meshed_anew(options.cgmesh, options.scratch, tagged)
        test_boundary_labels_kept(options.cgmesh, options.scratch, tagged)
    failures = FAILURES + TestTaggedTriangles.FAILURES
    if failures:
        print("%d checks failed" % len(failures), file=sys.stderr)
        return 1
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
