"""A sliver-laden input through the command line: a box of two regions that TetGen fills with
pseudo-random points and no quality bound (`tetgen -pAi`), read from its .node and .ele files.
Template refinement meshes it anew first (the table's `input remeshed boxes`, the stats), keeps
both regions' volumes (`cgmesh check`), gives the same file at 1 and 2 threads, and ends far better
shaped than refining it as given. Refined as given (--no-improve-input), and with its facet
markers kept as tagged triangles (the .face file beside it), it warns and says why."""
import argparse
import json
import os
import random
import shutil
import subprocess
import sys

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


def refine(cgmesh, source, output, options):
    """(stats, stdout, stderr) of a successful run, or None."""
    stats = output + ".json"
    result = run(cgmesh, "refine", source, output, "--edge-length-factor", "0.5", "--partitions",
                 "16", "--stats", stats, *options)
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


def test_tagged_triangles_kept(cgmesh, scratch, tagged):
    ran = refine(cgmesh, tagged + ".ele", os.path.join(scratch, "tagged.ele"), [])
    if ran is None:
        return
    stats, table, warnings = ran
    check(stats["inputRemeshedBoxes"] == 0, "tagged triangles, yet meshed anew")
    check("sliver-laden-input-kept" in table and "tagged triangles" in warnings,
          "tagged triangles: no warning, or not why: " + warnings)


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
        test_tagged_triangles_kept(options.cgmesh, options.scratch, tagged)
    if FAILURES:
        print("%d checks failed" % len(FAILURES), file=sys.stderr)
        return 1
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
