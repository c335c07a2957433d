"""Drives the cgmesh executable: generate, refine (XML and legacy files, --stats), check, --help,
and the error paths (one line on stderr, non-zero exit, no output file)."""
import argparse
import json
import os
import shutil
import subprocess
import sys

FAILURES = []


def check(condition, message):
    if not condition:
        FAILURES.append(message)
        print("check failed: " + message, file=sys.stderr)


def run(cgmesh, *arguments):
    return subprocess.run([cgmesh, *arguments], capture_output=True, text=True)


# A legacy file holding one hexahedron: valid VTK, but not a tetrahedral mesh.
HEXAHEDRON_VTK = """# vtk DataFile Version 3.0
one hexahedron
ASCII
DATASET UNSTRUCTURED_GRID
POINTS 8 double
0 0 0 1 0 0 1 1 0 0 1 0 0 0 1 1 0 1 1 1 1 0 1 1
CELLS 1 9
8 0 1 2 3 4 5 6 7
CELL_TYPES 1
12
"""


def test_help(cgmesh):
    for command in (["--help"], ["refine", "--help"], ["generate", "--help"], ["check", "--help"]):
        result = run(cgmesh, *command)
        check(result.returncode == 0 and "usage" in result.stdout, "help for %s" % command)


def test_generate_refine_check(cgmesh, scratch):
    cube = os.path.join(scratch, "cube.vtu")
    result = run(cgmesh, "generate", "cube", "3", cube)
    check(result.returncode == 0 and os.path.isfile(cube), "generate: " + result.stderr)

    refined = os.path.join(scratch, "refined.vtu")
    stats = os.path.join(scratch, "stats.json")
    result = run(cgmesh, "refine", cube, refined, "--partitions", "4", "--iterations", "2",
                 "--edge-length-factor", "0.25", "--threads", "2", "--stats", stats)
    check(result.returncode == 0, "refine failed: " + result.stderr)
    check("partition" in result.stdout and "total" in result.stdout, "no timing table printed")
    with open(stats) as handle:
        statistics = json.load(handle)
    check(statistics["input"]["cells"] == 162, "input cell count in stats")
    check(statistics["output"]["cells"] == 64 * 162, "output cell count in stats")
    check(statistics["output"]["points"] > statistics["input"]["points"], "point counts")
    for key in ("colors", "partitions", "threads", "edgeLengthThreshold"):
        check(key in statistics, "stats lacks " + key)
    for phase in ("partition", "graph", "color", "adapt", "heal", "merge", "quality", "total"):
        check(phase in statistics["seconds"], "stats lacks seconds of " + phase)

    refined_one_thread = os.path.join(scratch, "refined-1.vtu")
    result = run(cgmesh, "refine", cube, refined_one_thread, "--partitions", "4", "--iterations",
                 "2", "--edge-length-factor", "0.25", "--threads", "1")
    with open(refined, "rb") as first, open(refined_one_thread, "rb") as second:
        check(first.read() == second.read(), "output files of 1 and 2 threads differ")

    result = run(cgmesh, "check", refined)
    check(result.returncode == 0 and "valid" in result.stdout, "check refined: " + result.stdout)

    legacy_in = os.path.join(scratch, "cube.vtk")
    legacy_out = os.path.join(scratch, "refined.vtk")
    check(run(cgmesh, "generate", "cube", "3", legacy_in).returncode == 0, "generate .vtk")
    result = run(cgmesh, "refine", legacy_in, legacy_out, "--max-edge-length", "0.2")
    check(result.returncode == 0 and os.path.isfile(legacy_out), "legacy refine: " + result.stderr)
    check(run(cgmesh, "check", legacy_out).returncode == 0, "check legacy output")


def expect_error(cgmesh, scratch, description, arguments, output):
    result = run(cgmesh, *arguments)
    lines = [line for line in result.stderr.strip().splitlines()
             if not line.startswith("cgmesh: warning:")]
    check(result.returncode != 0, description + ": exit status 0")
    check(len(lines) == 1 and lines[0].startswith("cgmesh: error:"),
          description + ": stderr is not one error line: %r" % result.stderr)
    leftovers = [name for name in os.listdir(scratch) if name.startswith(os.path.basename(output))]
    check(not leftovers, description + ": output files left behind: %s" % leftovers)


def test_errors(cgmesh, scratch):
    cube = os.path.join(scratch, "cube.vtu")
    hexahedron = os.path.join(scratch, "hexahedron.vtk")
    with open(hexahedron, "w") as handle:
        handle.write(HEXAHEDRON_VTK)
    out = os.path.join(scratch, "failed.vtu")
    cases = [
        ("missing input", ["refine", os.path.join(scratch, "missing.vtu"), out]),
        ("non-tetrahedral input", ["refine", hexahedron, out]),
        ("missing region array", ["refine", cube, out, "--region-array", "NoSuchArray"]),
        ("bad partitions", ["refine", cube, out, "--partitions", "zero"]),
        ("both thresholds", ["refine", cube, out, "--max-edge-length", "0.1",
                             "--edge-length-factor", "0.5"]),
        ("unknown option", ["refine", cube, out, "--colour", "greedy"]),
        ("unknown extension", ["refine", cube, os.path.join(scratch, "failed.stl")]),
        ("missing output directory", ["refine", cube, os.path.join(scratch, "no", "failed.vtu")]),
        ("unwritable output", ["refine", cube, os.path.join(scratch, "failed.vtu", "x.vtu")]),
        ("bad cube size", ["generate", "cube", "-2", out]),
        ("check non-tetrahedral", ["check", hexahedron]),
    ]
    for description, arguments in cases:
        expect_error(cgmesh, scratch, description, arguments, out)
    check(run(cgmesh, "frobnicate").returncode != 0, "unknown command accepted")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cgmesh", required=True)
    parser.add_argument("--scratch", required=True)
    options = parser.parse_args()
    shutil.rmtree(options.scratch, ignore_errors=True)
    os.makedirs(options.scratch)
    test_help(options.cgmesh)
    test_generate_refine_check(options.cgmesh, options.scratch)
    test_errors(options.cgmesh, options.scratch)
    if FAILURES:
        print("%d checks failed" % len(FAILURES), file=sys.stderr)
        return 1
    print("all command-line checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
