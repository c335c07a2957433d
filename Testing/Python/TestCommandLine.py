"""Drives the cgmesh executable: generate, refine (XML and legacy files, --stats, every colouring,
partitioning by region, the Delaunay method, quality improvement options and the quality summary),
the serial tetgen baseline, check, --help, the error paths (one line on stderr, non-zero exit,
no output file), the checks made before refining, and --compression."""
import argparse
import hashlib
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time

FAILURES = []


def check(condition, message):
    if not condition:
        FAILURES.append(message)
        print("check failed: " + message, file=sys.stderr)


def run(cgmesh, *arguments):
    return subprocess.run([cgmesh, *arguments], capture_output=True, text=True)


def timed_run(cgmesh, *arguments):
    """(result, seconds) of one cgmesh run."""
    start = time.monotonic()
    result = run(cgmesh, *arguments)
    return result, time.monotonic() - start


def digest(path):
    with open(path, "rb") as handle:
        return hashlib.sha256(handle.read()).hexdigest()


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


COLORINGS = ("greedy", "greedy-lu", "iterative", "recoloring")


def test_help(cgmesh):
    for command in (["--help"], ["refine", "--help"], ["generate", "--help"], ["check", "--help"],
                    ["tetgen", "--help"]):
        result = run(cgmesh, *command)
        check(result.returncode == 0 and "usage" in result.stdout, "help for %s" % command)
    check("tetgen" in run(cgmesh, "--help").stdout, "cgmesh --help does not list tetgen")
    refine_help = run(cgmesh, "refine", "--help").stdout
    for text in ("--coloring", "--partition-by-region", "--partitions-per-region", *COLORINGS,
                 "--method", "delaunay", "--max-volume", "--volume-factor", "--radius-edge-ratio",
                 "--no-improve", "--improve-passes", "mean ratio", "NearFormerInterface",
                 "--max-cells", "--compression", "none (default)", "M tets/s"):
        check(text in refine_help, "refine --help does not mention " + text)
    tetgen_help = run(cgmesh, "tetgen", "--help").stdout
    for text in ("--max-volume", "--radius-edge-ratio", "--region-array", "--stats", "rQq",
                 "--compression", "--tet-order"):
        check(text in tetgen_help, "tetgen --help does not mention " + text)
    check("--compression" in run(cgmesh, "generate", "--help").stdout,
          "generate --help does not mention --compression")


def check_color_populations(statistics, description):
    """The colour populations of a --stats file add up and match the balance figure."""
    for key in ("coloring", "partitionsPerColor", "cellsPerColor", "colorBalance",
                "partitionByRegion", "partitionsPerRegion"):
        check(key in statistics, description + ": stats lacks " + key)
    partitions_per_color = statistics.get("partitionsPerColor", [])
    cells_per_color = statistics.get("cellsPerColor", [])
    check(len(partitions_per_color) == statistics["colors"]
          and len(cells_per_color) == statistics["colors"],
          description + ": not one population entry per colour")
    check(sum(partitions_per_color) == statistics["partitions"],
          description + ": partitionsPerColor does not add up to the partitions")
    check(sum(cells_per_color) == statistics["output"]["cells"],
          description + ": cellsPerColor does not add up to the output cells")
    if partitions_per_color:
        mean = statistics["partitions"] / len(partitions_per_color)
        check(abs(statistics["colorBalance"] - max(partitions_per_color) / mean) < 1e-9,
              description + ": colorBalance is not the largest colour over the mean")


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
    for phase in ("partition", "graph", "color", "adapt", "heal", "merge", "input", "output",
                  "quality", "total"):
        check(phase in statistics["seconds"], "stats lacks seconds of " + phase)
    check(statistics.get("coloring") == "greedy-lu", "default colouring in stats")
    check(statistics.get("partitionByRegion") is False, "partitionByRegion default in stats")
    check(statistics.get("method") == "template", "default method in stats")
    check(statistics.get("volumeBound") == 0 and statistics.get("delaunayFallbacks") == 0
          and statistics.get("fallbackPartitions") == [] and statistics.get("tetgenPoints") == 0,
          "template run: Delaunay figures in stats are not zero")
    check_color_populations(statistics, "default colouring")
    for text in ("coloring", "partitions per color", "cells per color", "color balance"):
        check(text in result.stdout, "the table lacks " + text)

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


def test_colorings(cgmesh, scratch):
    """Every colouring refines the cube, reports itself and its populations, and gives the same
    file for 1 and 2 threads."""
    cube = os.path.join(scratch, "cube.vtu")
    balance = {}
    for coloring in COLORINGS:
        outputs = []
        for threads in ("1", "2"):
            refined = os.path.join(scratch, "refined-%s-%s.vtu" % (coloring, threads))
            stats = os.path.join(scratch, "stats-%s-%s.json" % (coloring, threads))
            result = run(cgmesh, "refine", cube, refined, "--partitions", "16",
                         "--edge-length-factor", "0.25", "--threads", threads,
                         "--coloring", coloring, "--stats", stats)
            check(result.returncode == 0, "refine --coloring %s: %s" % (coloring, result.stderr))
            if result.returncode != 0:
                break
            with open(stats) as handle:
                statistics = json.load(handle)
            check(statistics["coloring"] == coloring, "stats name %s" % statistics["coloring"])
            check_color_populations(statistics, coloring)
            check(coloring in result.stdout, "the table does not name " + coloring)
            balance[coloring] = statistics["colorBalance"]
            with open(refined, "rb") as handle:
                outputs.append(handle.read())
        check(len(outputs) == 2 and outputs[0] == outputs[1],
              "--coloring %s: output files of 1 and 2 threads differ" % coloring)
        check(run(cgmesh, "check", refined).returncode == 0, "check --coloring " + coloring)
    print("colour balance on the 3^3 cube, 16 partitions: %s" % balance)


def test_partition_by_region(cgmesh, scratch):
    finfet = os.path.join(scratch, "finfet.vtu")
    result = run(cgmesh, "generate", "finfet", finfet, "--cells", "3000")
    check(result.returncode == 0, "generate finfet: " + result.stderr)
    refined = os.path.join(scratch, "finfet-refined.vtu")
    stats = os.path.join(scratch, "finfet.json")
    result = run(cgmesh, "refine", finfet, refined, "--region-array", "Material",
                 "--partition-by-region", "--partitions-per-region", "2", "--threads", "2",
                 "--stats", stats)
    check(result.returncode == 0, "refine --partition-by-region: " + result.stderr)
    check("by region" in result.stdout, "the table does not say the partitions follow regions")
    with open(stats) as handle:
        statistics = json.load(handle)
    check(statistics["partitionByRegion"] is True, "partitionByRegion in stats")
    check(statistics["partitionsPerRegion"] == 2, "partitionsPerRegion in stats")
    check(statistics["partitions"] > 1, "partitions by region: %d" % statistics["partitions"])
    check_color_populations(statistics, "partition by region")
    # More partitions per region than any region has tets: one per tet, with a warning.
    result = run(cgmesh, "refine", finfet, os.path.join(scratch, "finfet-many.vtu"),
                 "--region-array", "Material", "--partition-by-region",
                 "--partitions-per-region", "100000", "--stats", stats)
    check(result.returncode == 0 and "requested 100000 partitions per region, but" in
          result.stderr, "--partitions-per-region 100000: %r" % result.stderr)
    with open(stats) as handle:
        many = json.load(handle)
    check(many["partitions"] == many["input"]["cells"] and
          [warning["kind"] for warning in many["warnings"]] == ["partitions-reduced"],
          "--partitions-per-region 100000: %d partitions, warnings %s"
          % (many["partitions"], many["warnings"]))
    result = run(cgmesh, "check", refined, "--region-array", "Material")
    check(result.returncode == 0, "check the refined FinFET: " + result.stdout)


def region_volumes(cgmesh, mesh, array="Material"):
    """{region id: volume} from `cgmesh check --region-array ARRAY`, and the exit status."""
    result = run(cgmesh, "check", mesh, "--region-array", array)
    volumes = {}
    for line in result.stdout.splitlines():
        words = line.split()
        if len(words) == 3 and words[0] == "region" and words[1].lstrip("-").isdigit():
            volumes[int(words[1])] = float(words[2])
    return volumes, result.returncode


def test_delaunay(cgmesh, scratch):
    """--method delaunay on the FinFET: valid, regions kept, the same file for 1 and 2 threads,
    the Delaunay figures in the table and the stats."""
    finfet = os.path.join(scratch, "finfet.vtu")
    outputs = []
    for threads in ("1", "2"):
        refined = os.path.join(scratch, "finfet-delaunay-%s.vtu" % threads)
        stats = os.path.join(scratch, "finfet-delaunay-%s.json" % threads)
        result = run(cgmesh, "refine", finfet, refined, "--region-array", "Material",
                     "--partitions", "8", "--method", "delaunay", "--volume-factor", "0.3",
                     "--radius-edge-ratio", "1.8", "--threads", threads, "--stats", stats)
        check(result.returncode == 0, "refine --method delaunay: " + result.stderr)
        if result.returncode != 0:
            return
        for text in ("method", "delaunay", "volume bound", "tetgen points", "delaunay fallbacks"):
            check(text in result.stdout, "the Delaunay table lacks " + text)
        with open(stats) as handle:
            statistics = json.load(handle)
        check(statistics["method"] == "delaunay", "method in stats")
        check(statistics["volumeBound"] > 0 and statistics["tetgenPoints"] > 0,
              "volumeBound/tetgenPoints in stats")
        check(len(statistics["fallbackPartitions"]) == statistics["delaunayFallbacks"],
              "fallbackPartitions does not list every fallback")
        check(statistics["output"]["cells"] > 2 * statistics["input"]["cells"], "hardly refined")
        with open(refined, "rb") as handle:
            outputs.append(handle.read())
    check(outputs[0] == outputs[1], "Delaunay output files of 1 and 2 threads differ")
    check(statistics["partitioner"] == "curve-chunks", "Delaunay's automatic partitioner")
    # Below 400,000 tets the curve chunks are one: METIS on the whole mesh, the same file.
    refined = os.path.join(scratch, "finfet-delaunay-metis.vtu")
    result = run(cgmesh, "refine", finfet, refined, "--region-array", "Material",
                 "--partitions", "8", "--method", "delaunay", "--volume-factor", "0.3",
                 "--radius-edge-ratio", "1.8", "--threads", "2", "--partitioner", "metis")
    check(result.returncode == 0, "refine --partitioner metis: " + result.stderr)
    same = subprocess.run([sys.executable, "-c", SAME_MESH_AND_CELL_ARRAYS, refined,
                           os.path.join(scratch, "finfet-delaunay-2.vtu")],
                          capture_output=True, text=True)
    check(same.returncode == 0 and same.stdout.strip() == "same",
          "a small mesh in curve chunks is not METIS' partition: " + same.stdout + same.stderr)
    before, _ = region_volumes(cgmesh, finfet)
    after, status = region_volumes(cgmesh, refined)
    check(status == 0, "check the Delaunay-refined FinFET")
    check(len(before) > 1 and before.keys() == after.keys() and all(
        abs(after[region] - volume) <= 1e-9 * volume for region, volume in before.items()),
        "Delaunay region volumes %s != input %s" % (after, before))

    cube = os.path.join(scratch, "cube.vtu")
    stats = os.path.join(scratch, "cube-delaunay.json")
    result = run(cgmesh, "refine", cube, os.path.join(scratch, "cube-delaunay.vtu"),
                 "--partitions", "4", "--method", "delaunay", "--max-volume", "0.0005",
                 "--stats", stats)
    check(result.returncode == 0, "refine --max-volume: " + result.stderr)
    with open(stats) as handle:
        check(json.load(handle)["volumeBound"] == 0.0005, "--max-volume is not the bound")


# Prints "same" when two files hold the same points, cells and cell arrays (their field data, such
# as the partitioner's index, may differ).
SAME_MESH_AND_CELL_ARRAYS = """import sys
import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
def read(path):
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    cells = grid.GetCellData()
    arrays = {cells.GetArrayName(i): vtk_to_numpy(cells.GetArray(i))
              for i in range(cells.GetNumberOfArrays())}
    return (vtk_to_numpy(grid.GetPoints().GetData()),
            vtk_to_numpy(grid.GetCells().GetConnectivityArray()), arrays)
first, second = read(sys.argv[1]), read(sys.argv[2])
same = (numpy.array_equal(first[0], second[0]) and numpy.array_equal(first[1], second[1]) and
        first[2].keys() == second[2].keys() and len(first[2]) > 2 and
        all(numpy.array_equal(first[2][name], second[2][name]) for name in first[2]))
print("same" if same else "different")
"""


# Computes the quality summary of a refined file from its cell arrays, as numpy does, to check the
# figures cgmesh reports; prints them as JSON.
QUALITY_FROM_ARRAYS = """import json, sys
import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
reader = vtkXMLUnstructuredGridReader()
reader.SetFileName(sys.argv[1])
reader.Update()
cells = reader.GetOutput().GetCellData()
angles = vtk_to_numpy(cells.GetArray("MinDihedralAngle"))
ratios = vtk_to_numpy(cells.GetArray("EdgeRatio"))
near = vtk_to_numpy(cells.GetArray("NearFormerInterface")) != 0
summary = {}
for name, chosen in (("all", near | ~near), ("interior", ~near), ("nearFormerInterfaces", near)):
    summary[name] = {"tets": int(chosen.sum()), "minDihedralAngleMin": float(angles[chosen].min()),
                     "minDihedralAngleP1": float(numpy.percentile(angles[chosen], 1)),
                     "edgeRatioP99": float(numpy.percentile(ratios[chosen], 99))}
print(json.dumps(summary))
"""


def refine_with_improvement_options(cgmesh, scratch, name, options):
    """Refines the FinFET with `options`; returns (stats, table, output file) or None."""
    finfet = os.path.join(scratch, "finfet.vtu")
    refined = os.path.join(scratch, "finfet-%s.vtu" % name)
    stats = os.path.join(scratch, "finfet-%s.json" % name)
    result = run(cgmesh, "refine", finfet, refined, "--region-array", "Material", "--partitions",
                 "8", "--edge-length-factor", "1.0", "--threads", "2", "--stats", stats, *options)
    check(result.returncode == 0, "refine %s: %s" % (" ".join(options), result.stderr))
    if result.returncode != 0:
        return None
    with open(stats) as handle:
        return json.load(handle), result.stdout, refined


def check_quality_summary(statistics, refined, description):
    """The quality summary splits the tets by NearFormerInterface and matches numpy's figures."""
    quality = statistics["quality"]
    check(quality["interior"]["tets"] + quality["nearFormerInterfaces"]["tets"]
          == quality["all"]["tets"] == statistics["output"]["cells"],
          description + ": the quality groups do not add up to the output cells")
    check(quality["interior"]["tets"] > 0 and quality["nearFormerInterfaces"]["tets"] > 0,
          description + ": a quality group is empty")
    result = subprocess.run([sys.executable, "-c", QUALITY_FROM_ARRAYS, refined],
                            capture_output=True, text=True)
    check(result.returncode == 0, description + ": cannot read the output: " + result.stderr)
    if result.returncode != 0:
        return
    expected = json.loads(result.stdout)
    for group, figures in expected.items():
        for key, value in figures.items():
            check(abs(quality[group][key] - value) <= 1e-9 * max(1.0, abs(value)),
                  "%s: quality %s %s is %s, numpy says %s"
                  % (description, group, key, quality[group][key], value))


def test_improvement_options(cgmesh, scratch):
    """--no-improve and --improve-passes reach the filter and the reports; the quality summary
    is right and improvement raises the worst quality of the FinFET."""
    runs = {}
    for name, options in (("improved", []), ("passes-3", ["--improve-passes", "3"]),
                          ("passes-0", ["--improve-passes", "0"]),
                          ("not-improved", ["--no-improve"])):
        runs[name] = refine_with_improvement_options(cgmesh, scratch, name, options)
        if runs[name] is None:
            return
    improved, table, refined = runs["improved"]
    for text in ("improvement", "edge removals", "face swaps", "vertex moves", "improve seconds",
                 "interior", "near former interfaces", "min dihedral p1", "edge ratio p99"):
        check(text in table, "the table lacks " + text)
    improvement = improved["improvement"]
    check(improvement["enabled"] is True and improvement["passes"] == 2, "improvement defaults")
    check(improvement["edgeRemovals"] + improvement["faceSwaps"] + improvement["vertexMoves"] > 0,
          "the default run improved nothing")
    check(all(0 <= improvement["input"][key] <= improvement[key]
              for key in ("edgeRemovals", "faceSwaps", "vertexMoves")),
          "the input's improvement counts are not part of the counts")
    check("of them on the input" in table, "the table lacks the input's improvement counts")
    check(improvement["seconds"] == improved["seconds"]["improve"]
          and 0 < improvement["shareOfTotal"] < 1, "improve seconds and share in stats")
    check_quality_summary(improved, refined, "improved")
    check(runs["passes-3"][0]["improvement"]["passes"] == 3, "--improve-passes 3 in stats")
    for name in ("passes-0", "not-improved"):
        statistics, _, output = runs[name]
        figures = statistics["improvement"]
        check(figures["edgeRemovals"] == figures["faceSwaps"] == figures["vertexMoves"] == 0
              and not any(figures["input"].values()), name + ": improvement counts are not 0")
        check_quality_summary(statistics, output, name)
    check(runs["not-improved"][0]["improvement"]["enabled"] is False, "--no-improve in stats")
    check("improvement             off" in runs["not-improved"][1], "the table lacks 'off'")
    before = runs["not-improved"][0]["quality"]["all"]
    after = improved["quality"]["all"]
    check(after["edgeRatioP99"] < before["edgeRatioP99"],
          "improvement did not lower the 99th percentile of the edge ratio: %s" % after)
    check(run(cgmesh, "check", refined, "--region-array", "Material").returncode == 0,
          "check the improved FinFET")


def test_tetgen(cgmesh, scratch):
    """The serial baseline on the FinFET, with the tets along a Hilbert curve (the default) and in
    the input's order: valid, every region's volume kept, quality arrays and stats written."""
    finfet = os.path.join(scratch, "finfet.vtu")
    before, _ = region_volumes(cgmesh, finfet)
    volume = sum(before.values())
    for order in ("hilbert", "input"):
        refined = os.path.join(scratch, "finfet-tetgen-%s.vtu" % order)
        stats = os.path.join(scratch, "finfet-tetgen-%s.json" % order)
        options = [] if order == "hilbert" else ["--tet-order", order]
        result = run(cgmesh, "tetgen", finfet, refined, "--max-volume", str(0.3 * volume / 3000),
                     "--radius-edge-ratio", "2", "--region-array", "Material", "--stats", stats,
                     *options)
        check(result.returncode == 0, "tetgen %s: %s" % (order, result.stderr))
        if result.returncode != 0:
            continue
        check("tetgen" in result.stdout and "rQq2a" in result.stdout,
              "tetgen table: " + result.stdout)
        with open(stats) as handle:
            statistics = json.load(handle)
        for phase in ("tetgen", "quality", "read", "write", "total"):
            check(phase in statistics["seconds"], "tetgen stats lack seconds of " + phase)
        check(statistics["output"]["cells"] > 2 * statistics["input"]["cells"],
              "tetgen: no refinement")
        check(statistics["tetgenPoints"] > 0 and statistics["switches"].startswith("rQq2a"),
              "tetgen stats: points/switches")
        check(statistics.get("tetOrder") == order, "tetgen stats: tetOrder %s" % order)
        after, status = region_volumes(cgmesh, refined)
        check(status == 0, "check the TetGen-refined FinFET (%s order)" % order)
        check(before.keys() == after.keys() and all(
            abs(after[region] - volume) <= 1e-9 * volume for region, volume in before.items()),
            "TetGen region volumes %s != input %s" % (after, before))
        reader_check = subprocess.run(
            [sys.executable, "-c", "import sys\nfrom vtkmodules.vtkIOXML import "
             "vtkXMLUnstructuredGridReader\nr = vtkXMLUnstructuredGridReader()\n"
             "r.SetFileName(sys.argv[1])\nr.Update()\ncd = r.GetOutput().GetCellData()\n"
             "sys.exit(0 if cd.GetArray('EdgeRatio') and cd.GetArray('MinDihedralAngle') "
             "and cd.GetArray('Material') else 1)", refined], capture_output=True, text=True)
        check(reader_check.returncode == 0,
              "tetgen output lacks EdgeRatio/MinDihedralAngle/Material")


def expect_error(cgmesh, scratch, description, arguments, output, exit_status=None):
    result = run(cgmesh, *arguments)
    lines = [line for line in result.stderr.strip().splitlines()
             if not line.startswith("cgmesh: warning:")]
    check(result.returncode != 0, description + ": exit status 0")
    check(exit_status is None or result.returncode == exit_status,
          description + ": exit status %d, expected %s" % (result.returncode, exit_status))
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
        ("tetgen non-tetrahedral input", ["tetgen", hexahedron, out, "--max-volume", "0.01"]),
        ("tetgen missing region array", ["tetgen", cube, out, "--max-volume", "0.01",
                                         "--region-array", "NoSuchArray"]),
        ("size guard", ["refine", cube, out, "--max-cells", "100"]),
    ]
    for description, arguments in cases:
        expect_error(cgmesh, scratch, description, arguments, out)

    # Usage errors: exit status 2.
    usage_cases = [
        ("unknown colouring", ["refine", cube, out, "--coloring", "rainbow"]),
        ("colouring by label", ["refine", cube, out, "--coloring", "Greedy-LU"]),
        ("partitions per region alone", ["refine", cube, out, "--partitions-per-region", "2"]),
        ("partition by region without regions", ["refine", cube, out, "--partition-by-region"]),
        ("partition by region with a value", ["refine", cube, out, "--region-array", "Material",
                                              "--partition-by-region=yes"]),
        ("partitions and partition by region", ["refine", cube, out, "--partitions", "4",
                                                "--region-array", "Material",
                                                "--partition-by-region"]),
        ("zero partitions per region", ["refine", cube, out, "--region-array", "Material",
                                        "--partition-by-region", "--partitions-per-region", "0"]),
        ("unknown method", ["refine", cube, out, "--method", "voronoi"]),
        ("volume bound with templates", ["refine", cube, out, "--max-volume", "0.01"]),
        ("edge length with Delaunay", ["refine", cube, out, "--method", "delaunay",
                                       "--edge-length-factor", "0.5"]),
        ("both volume bounds", ["refine", cube, out, "--method", "delaunay", "--max-volume",
                                "0.01", "--volume-factor", "0.1"]),
        ("radius-edge ratio below 1", ["refine", cube, out, "--method", "delaunay",
                                       "--radius-edge-ratio", "0.5"]),
        ("too many improvement passes", ["refine", cube, out, "--improve-passes", "21"]),
        ("negative improvement passes", ["refine", cube, out, "--improve-passes", "-1"]),
        ("no-improve with passes", ["refine", cube, out, "--no-improve", "--improve-passes", "2"]),
        ("no-improve with a value", ["refine", cube, out, "--no-improve=yes"]),
        ("negative cell limit", ["refine", cube, out, "--max-cells", "-1"]),
        ("non-integer cell limit", ["refine", cube, out, "--max-cells", "1e6"]),
        ("tetgen without --max-volume", ["tetgen", cube, out]),
        ("tetgen with a zero bound", ["tetgen", cube, out, "--max-volume", "0"]),
        ("tetgen unknown option", ["tetgen", cube, out, "--max-volume", "0.01", "--threads", "2"]),
        ("tetgen unknown order", ["tetgen", cube, out, "--max-volume", "0.01", "--tet-order",
                                  "random"]),
        ("tetgen without OUT", ["tetgen", cube, "--max-volume", "0.01"]),
    ]
    for description, arguments in usage_cases:
        expect_error(cgmesh, scratch, description, arguments, out, exit_status=2)
    result = run(cgmesh, "refine", cube, out, "--max-cells", "100")
    check("limit of 100" in result.stderr and "MaximumNumberOfCells" in result.stderr,
          "the size-guard error does not name the limit: " + result.stderr)
    result = run(cgmesh, "refine", cube, out, "--coloring", "rainbow")
    check("rainbow" in result.stderr and "greedy-lu" in result.stderr,
          "the unknown-colouring error does not name the choices: " + result.stderr)
    check(run(cgmesh, "frobnicate").returncode != 0, "unknown command accepted")

# Seconds within which a run refused before refining must end: its refinement would take far
# longer, and reading a small input takes milliseconds.
FAST_SECONDS = 3.0


def expect_early_error(cgmesh, scratch, description, arguments, output, exit_status, *texts):
    """An error before refining: the exit status, one error line holding `texts`, no table (it is
    printed after the refinement), no output file, and quickly. Returns stderr."""
    result, seconds = timed_run(cgmesh, *arguments)
    expect_error(cgmesh, scratch, description, arguments, output, exit_status)
    for text in texts:
        check(text in result.stderr, "%s: the error lacks %r: %r" % (description, text, result.stderr))
    check(result.stdout == "", description + ": it refined before failing: " + result.stdout[:200])
    check(seconds < FAST_SECONDS, "%s: took %.1f s, expected a refusal before refining"
          % (description, seconds))
    return result.stderr


def test_stats_checked_first(cgmesh, scratch):
    """--stats in a missing directory fails like OUT would, before the refinement."""
    cube10 = os.path.join(scratch, "cube10.vtu")
    out = os.path.join(scratch, "early.vtu")
    missing = os.path.join(scratch, "no-such-directory", "s.json")
    expect_early_error(cgmesh, scratch, "stats in a missing directory",
                       ["refine", cube10, out, "--iterations", "3", "--edge-length-factor", "0.25",
                        "--stats", missing], out, 1,
                       "cannot write statistics file '%s'" % missing, "does not exist")
    check(not os.path.exists(os.path.dirname(missing)), "the stats directory was created")
    expect_early_error(cgmesh, scratch, "tetgen stats in a missing directory",
                       ["tetgen", cube10, out, "--max-volume", "1e-5", "--stats", missing], out, 1,
                       "cannot write statistics file")
    # A file where the directory should be is named as such.
    not_a_directory = os.path.join(cube10, "out.vtu")
    expect_early_error(cgmesh, scratch, "output under a file",
                       ["refine", cube10, not_a_directory], not_a_directory, 1,
                       "cannot write output file", "'%s' is not a directory" % cube10)
    # A directory whose mode bits let root write where the file system does not (/proc): found by
    # opening the file, before the refinement.
    if os.path.isdir("/proc/self"):
        refused = "/proc/cgmesh-out.vtu"
        expect_early_error(cgmesh, scratch, "output where the file system refuses it",
                           ["refine", cube10, refused, "--iterations", "3",
                            "--edge-length-factor", "0.25"], refused, 1,
                           "cannot write output file '%s'" % refused)


def test_output_is_not_input(cgmesh, scratch):
    """OUT naming IN, by any spelling or a link, is a usage error and leaves IN untouched."""
    cube = os.path.join(scratch, "cube.vtu")
    before = digest(cube)
    link = os.path.join(scratch, "cube-link.vtu")
    if os.path.lexists(link):
        os.remove(link)
    os.symlink(cube, link)
    spellings = (cube, os.path.join(scratch, ".", "cube.vtu"),
                 os.path.join(scratch, "..", os.path.basename(scratch), "cube.vtu"), link)
    for spelling in spellings:
        result = run(cgmesh, "refine", cube, spelling)
        check(result.returncode == 2, "OUT %s = IN: exit status %d" % (spelling, result.returncode))
        check("is the same file as IN" in result.stderr and "would overwrite IN" in result.stderr,
              "OUT %s = IN: %r" % (spelling, result.stderr))
        check(result.stdout == "", "OUT %s = IN: it refined" % spelling)
    for arguments in (["--stats", cube], ["--stats", os.path.join(scratch, "same.vtu")]):
        result = run(cgmesh, "refine", cube, os.path.join(scratch, "same.vtu"), *arguments)
        check(result.returncode == 2 and "is the same file as" in result.stderr,
              "--stats %s: %r" % (arguments[1], result.stderr))
    result = run(cgmesh, "tetgen", cube, link, "--max-volume", "0.01")
    check(result.returncode == 2 and "is the same file as IN" in result.stderr,
          "tetgen OUT = IN: %r" % result.stderr)
    check(digest(cube) == before and not os.path.islink(cube), "the input was changed")
    check(os.path.islink(link), "the link was replaced")
    os.remove(link)


def test_option_values(cgmesh, scratch):
    """Out-of-range values and mistyped options are usage errors, named as such."""
    cube = os.path.join(scratch, "cube.vtu")
    out = os.path.join(scratch, "options.vtu")
    for arguments, text in (
            (["--edge-length-factor", "0"], "--edge-length-factor must be a number > 0, got '0'"),
            (["--method", "delaunay", "--volume-factor", "0"],
             "--volume-factor must be a number > 0, got '0'"),
            (["--no-improv"], "unknown option '--no-improv' (did you mean '--no-improve'?)"),
            (["--no-improv", "--threads", "2"], "unknown option '--no-improv'"),
            (["-p", "4"], "unknown option '-p'"),
            (["--colour", "greedy"], "unknown option '--colour' (did you mean '--coloring'?)"),
            (["--stats", "--threads", "2"], "option --stats needs a value"),
            (["--compression", "gzip"], "unknown compression 'gzip' for --compression (use none, "
                                        "lz4, zlib)")):
        expect_early_error(cgmesh, scratch, " ".join(arguments), ["refine", cube, out, *arguments],
                           out, 2, text)
    # Recognised before the positionals are counted, wherever they stand.
    expect_early_error(cgmesh, scratch, "typo before IN", ["refine", "--partitons", "4", cube, out],
                       out, 2, "unknown option '--partitons' (did you mean '--partitions'?)")
    expect_early_error(cgmesh, scratch, "check typo", ["check", cube, "--region", "Material"], out,
                       2, "unknown option '--region'")
    # A negative number is a value, not an option.
    expect_early_error(cgmesh, scratch, "negative cube size", ["generate", "cube", "-2", out], out,
                       2, "N must be an integer in [1, 1000], got '-2'")


def test_nothing_refined(cgmesh, scratch):
    """A threshold above every edge: exit 0, with a warning giving the threshold and the longest
    edge."""
    cube = os.path.join(scratch, "cube.vtu")
    stats = os.path.join(scratch, "unrefined.json")
    result = run(cgmesh, "refine", cube, os.path.join(scratch, "unrefined.vtu"),
                 "--edge-length-factor", "5", "--stats", stats)
    check(result.returncode == 0, "factor 5: " + result.stderr)
    if result.returncode != 0:
        return
    with open(stats) as handle:
        statistics = json.load(handle)
    check(statistics["output"]["cells"] == statistics["input"]["cells"], "factor 5 refined")
    check([warning["kind"] for warning in statistics["warnings"]] == ["nothing-refined"],
          "factor 5: the stats' warnings are %s" % statistics["warnings"])
    check("nothing-refined 1" in result.stdout, "factor 5: the table does not count the warning")
    found = re.search(r"cgmesh: warning: nothing was refined: no edge is longer than the threshold "
                      r"(\S+) \(--edge-length-factor 5 x the mean edge length (\S+)\); the longest "
                      r"edge is (\S+)", result.stderr)
    check(found is not None, "factor 5: no nothing-refined warning: %r" % result.stderr)
    if found:
        threshold, mean, longest = (float(value) for value in found.groups())
        check(math.isclose(threshold, statistics["edgeLengthThreshold"], rel_tol=1e-5),
              "the warning's threshold %s is not the run's" % threshold)
        check(math.isclose(threshold, 5 * mean, rel_tol=1e-5), "threshold is not 5 x the mean")
        check(math.isclose(longest, math.sqrt(3) / 3, rel_tol=1e-5),
              "the longest edge of the 3^3 Kuhn cube is sqrt(3)/3, not %s" % longest)
    result = run(cgmesh, "refine", cube, os.path.join(scratch, "unrefined-delaunay.vtu"),
                 "--method", "delaunay", "--max-volume", "10")
    check(result.returncode == 0 and "cgmesh: warning: nothing was refined: TetGen inserted no "
          "point under the volume bound 10" in result.stderr,
          "Delaunay, nothing refined: %r" % result.stderr)
    # A box that selects no tet: every long edge lies outside it.
    result = run(cgmesh, "refine", cube, os.path.join(scratch, "unrefined-box.vtu"),
                 "--refine-box", "5,5,5,6,6,6", "--stats", stats)
    check(result.returncode == 0 and "cgmesh: warning: nothing was refined: no edge between two "
          "points of the selected tets (--refine-box 5,5,5,6,6,6) is longer than the threshold"
          in result.stderr, "empty box, nothing refined: %r" % result.stderr)
    with open(stats) as handle:
        statistics = json.load(handle)
    check(statistics["output"]["cells"] == statistics["input"]["cells"] and
          statistics["improvement"]["edgeRemovals"] == 0, "an empty box changed the mesh")
    result = run(cgmesh, "refine", cube, os.path.join(scratch, "refined-again.vtu"))
    check("nothing was refined" not in result.stderr, "a refining run warned: " + result.stderr)


# Copies a .vtu, adding the vtkStringArray cell array 'Names'.
ADD_STRING_ARRAY = """import sys
from vtkmodules.vtkCommonCore import vtkStringArray
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader, vtkXMLUnstructuredGridWriter
reader = vtkXMLUnstructuredGridReader()
reader.SetFileName(sys.argv[1])
reader.Update()
grid = reader.GetOutput()
names = vtkStringArray()
names.SetName("Names")
for cell in range(grid.GetNumberOfCells()):
    names.InsertNextValue("cell")
grid.GetCellData().AddArray(names)
writer = vtkXMLUnstructuredGridWriter()
writer.SetInputData(grid)
writer.SetFileName(sys.argv[2])
sys.exit(0 if writer.Write() == 1 else 1)
"""


def test_region_array_named(cgmesh, scratch):
    """A missing or non-numeric --region-array is named with the cell arrays there are (exit 1)."""
    refined = os.path.join(scratch, "refined.vtu")
    out = os.path.join(scratch, "regions.vtu")
    for command in (["refine", refined, out], ["tetgen", refined, out, "--max-volume", "0.01"],
                    ["check", refined]):
        stderr = expect_early_error(
            cgmesh, scratch, command[0] + " missing region array",
            [*command, "--region-array", "NoSuchArray"], out, 1,
            "has no cell array 'NoSuchArray' (--region-array); its cell arrays: ")
        for name in ("'PartitionId'", "'ColorId'", "'EdgeRatio'", "'MinDihedralAngle'"):
            check(name in stderr, "%s: the error does not list %s: %r" % (command[0], name, stderr))
    cube = os.path.join(scratch, "cube.vtu")
    expect_early_error(cgmesh, scratch, "region array of an input without arrays",
                       ["refine", cube, out, "--region-array", "Material"], out, 1,
                       "has no cell array 'Material' (--region-array); its cell arrays: none")
    named = os.path.join(scratch, "named.vtu")
    if subprocess.run([sys.executable, "-c", ADD_STRING_ARRAY, cube, named]).returncode == 0:
        expect_early_error(cgmesh, scratch, "non-numeric region array",
                           ["refine", named, out, "--region-array", "Names"], out, 1,
                           "cell array 'Names' of '%s' is not numeric" % named)
    else:
        check(False, "cannot write a file with a string cell array")


ADD_LABEL_ARRAYS = """import sys
from vtkmodules.vtkCommonCore import vtkIntArray
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader, vtkXMLUnstructuredGridWriter
reader = vtkXMLUnstructuredGridReader()
reader.SetFileName(sys.argv[1])
reader.Update()
grid = reader.GetOutput()
numbers, layers = vtkIntArray(), vtkIntArray()
numbers.SetName("CellNumber")
layers.SetName("Layer")
bounds = grid.GetBounds()
middle = 0.5 * (bounds[4] + bounds[5])
for cell in range(grid.GetNumberOfCells()):
    numbers.InsertNextValue(cell)
    ids = grid.GetCell(cell).GetPointIds()
    z = sum(grid.GetPoint(ids.GetId(k))[2] for k in range(4)) / 4
    layers.InsertNextValue(1 if z > middle else 0)
grid.GetCellData().AddArray(numbers)
grid.GetCellData().AddArray(layers)
contact = vtkIntArray()
contact.SetName("OnContact")
for point in range(grid.GetNumberOfPoints()):
    contact.InsertNextValue(1 if grid.GetPoint(point)[0] == bounds[0] else 0)
grid.GetPointData().AddArray(contact)
writer = vtkXMLUnstructuredGridWriter()
writer.SetInputData(grid)
writer.SetFileName(sys.argv[2])
sys.exit(0 if writer.Write() == 1 else 1)
"""


def test_material_labels_by_default(cgmesh, scratch):
    """Without --region-array the integer cell arrays are kept as material labels: the volume of
    every value of Material and of a second labelling is conserved, an id array and cgmesh's own
    output arrays are not taken for labels, and --refine-regions needs a named region array."""
    labelled = os.path.join(scratch, "labelled.vtu")
    if subprocess.run([sys.executable, "-c", ADD_LABEL_ARRAYS, os.path.join(scratch, "finfet.vtu"),
                       labelled]).returncode != 0:
        check(False, "cannot add label arrays to the FinFET")
        return
    refined = os.path.join(scratch, "labelled-refined.vtu")
    stats = os.path.join(scratch, "labelled-refined.json")
    result = run(cgmesh, "refine", labelled, refined, "--threads", "2", "--stats", stats)
    check(result.returncode == 0, "refine without --region-array: " + result.stderr)
    if result.returncode != 0:
        return
    with open(stats) as handle:
        statistics = json.load(handle)
    check(statistics.get("materialLabelArrays") == "Material,Layer",
          "material labels %r" % statistics.get("materialLabelArrays"))
    check("material labels" in result.stdout, "the table does not name the material labels")
    check(statistics["improvement"]["edgeRemovals"] > 0, "no improvement happened")
    for array in ("Material", "Layer"):
        before, _ = region_volumes(cgmesh, labelled, array)
        after, status = region_volumes(cgmesh, refined, array)
        check(status == 0, "check the refined FinFET by " + array)
        # `cgmesh check` prints 12 significant digits.
        check(len(before) > 1 and before.keys() == after.keys() and all(
            abs(after[value] - volume) <= 2e-11 * volume for value, volume in before.items()),
            "%s volumes %s != input %s" % (array, after, before))
    again = os.path.join(scratch, "labelled-again.vtu")
    result = run(cgmesh, "refine", refined, again, "--stats", stats)
    with open(stats) as handle:
        statistics = json.load(handle)
    check(result.returncode == 0 and statistics.get("materialLabelArrays") == "Material,Layer",
          "refining an output: labels %r" % statistics.get("materialLabelArrays"))
    refused = os.path.join(scratch, "labelled-refused.vtu")
    expect_early_error(cgmesh, scratch, "refine-regions without a region array",
                       ["refine", labelled, refused, "--refine-regions", "1"], refused, 1,
                       "RefinementRegions needs a region array")


MARKED_POINTS = """import sys
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
reader = vtkXMLUnstructuredGridReader()
reader.SetFileName(sys.argv[1])
reader.Update()
grid = reader.GetOutput()
contact = grid.GetPointData().GetArray(sys.argv[2])
xmin = grid.GetBounds()[0]
marked = [p for p in range(grid.GetNumberOfPoints()) if contact.GetComponent(p, 0) != 0]
off = [p for p in marked if grid.GetPoint(p)[0] != xmin]
on = [p for p in range(grid.GetNumberOfPoints()) if grid.GetPoint(p)[0] == xmin]
print(len(marked), len(off), len(on))
"""

# Adds OnContactFloat, OnContact as doubles (a flag as numpy or meshio stores it), with NaN at
# point argv[3] when it is not -1.
ADD_FLOAT_FLAGS = """import sys
from vtkmodules.vtkCommonCore import vtkDoubleArray
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader, vtkXMLUnstructuredGridWriter
reader = vtkXMLUnstructuredGridReader()
reader.SetFileName(sys.argv[1])
reader.Update()
grid = reader.GetOutput()
contact = grid.GetPointData().GetArray("OnContact")
flags = vtkDoubleArray()
flags.SetName("OnContactFloat")
for point in range(grid.GetNumberOfPoints()):
    flags.InsertNextValue(float(contact.GetValue(point)))
if int(sys.argv[3]) >= 0:
    flags.SetValue(int(sys.argv[3]), float("nan"))
grid.GetPointData().AddArray(flags)
writer = vtkXMLUnstructuredGridWriter()
writer.SetInputData(grid)
writer.SetFileName(sys.argv[2])
sys.exit(0 if writer.Write() == 1 else 1)
"""


def marked_points(path, array="OnContact"):
    """(marked, marked off the x = xmin plane, points on the plane) of a flag point array."""
    result = subprocess.run([sys.executable, "-c", MARKED_POINTS, path, array],
                            capture_output=True, text=True)
    check(result.returncode == 0, "cannot read %s of %s: %s" % (array, path, result.stderr))
    return tuple(int(word) for word in result.stdout.split()) if result.returncode == 0 else None


def test_point_labels(cgmesh, scratch):
    """An integer point array is a labelling: after refinement the OnContact node set marks
    exactly the points of its plane, new ones included; --interpolate-arrays interpolates and
    rounds it instead, which marks points off the plane."""
    labelled = os.path.join(scratch, "labelled.vtu")
    refined = os.path.join(scratch, "labelled-refined.vtu")
    before = marked_points(labelled)
    after = marked_points(refined)
    if before and after:
        check(before[0] == before[2] and before[0] > 0, "the input's node set %s" % (before,))
        check(after[1] == 0 and after[0] == after[2] and after[0] > before[0],
              "refined node set (marked, off the plane, on the plane) %s" % (after,))
    interpolated = os.path.join(scratch, "labelled-interpolated.vtu")
    result = run(cgmesh, "refine", labelled, interpolated, "--interpolate-arrays", "OnContact")
    check(result.returncode == 0, "refine --interpolate-arrays: " + result.stderr)
    rounded = marked_points(interpolated)
    if rounded:
        check(rounded[1] > 0, "--interpolate-arrays OnContact left it a labelling %s" % (rounded,))
    result = run(cgmesh, "refine", labelled, interpolated, "--interpolate-arrays", "OnContakt")
    check(result.returncode == 1 and "InterpolatedPointArrays names 'OnContakt'" in result.stderr
          and "'OnContact'" in result.stderr, "--interpolate-arrays with a typo: " + result.stderr)

    # The same flag stored as doubles: a field by default (interpolated: points off the plane get
    # 0.5), a labelling with --label-arrays, and refused when it holds a NaN.
    floats, with_nan = (os.path.join(scratch, name) for name in ("float-flags.vtu", "nan-flags.vtu"))
    for path, nan_point in ((floats, "-1"), (with_nan, "17")):
        made = subprocess.run([sys.executable, "-c", ADD_FLOAT_FLAGS, labelled, path, nan_point])
        check(made.returncode == 0, "cannot write " + path)
    output = os.path.join(scratch, "float-flags-refined.vtu")
    result = run(cgmesh, "refine", floats, output)
    as_field = marked_points(output, "OnContactFloat") if result.returncode == 0 else None
    check(as_field is not None and as_field[1] > 0,
          "a double flag array was not interpolated by default: %s %s" % (as_field, result.stderr))
    result = run(cgmesh, "refine", floats, output, "--label-arrays", "OnContactFloat")
    as_label = marked_points(output, "OnContactFloat") if result.returncode == 0 else None
    check(as_label is not None and as_label[1] == 0 and as_label[0] == as_label[2],
          "--label-arrays OnContactFloat: (marked, off the plane, on the plane) %s %s"
          % (as_label, result.stderr))
    refused = os.path.join(scratch, "nan-flags-refined.vtu")
    expect_early_error(cgmesh, scratch, "a NaN label",
                       ["refine", with_nan, refused, "--label-arrays", "OnContactFloat"], refused,
                       1, "point array 'OnContactFloat' (LabelPointArrays) holds nan at point 17")
    expect_early_error(cgmesh, scratch, "an array in both lists",
                       ["refine", floats, refused, "--label-arrays", "OnContactFloat",
                        "--interpolate-arrays", "OnContactFloat"], refused, 1,
                       "named both in InterpolatedPointArrays and in LabelPointArrays")


def test_size_forecast(cgmesh, scratch):
    """Several template iterations whose last must exceed --max-cells are refused before the
    first; a run at exactly the limit is not."""
    cube10 = os.path.join(scratch, "cube10.vtu")
    out = os.path.join(scratch, "forecast.vtu")
    expect_early_error(cgmesh, scratch, "10 iterations at 0.001",
                       ["refine", cube10, out, "--max-edge-length", "0.001", "--iterations", "10"],
                       out, 1, "refining would produce at least ", "in 10 iterations",
                       "more than the limit of 100000000 (--max-cells)", "refused before refining")
    cube = os.path.join(scratch, "cube.vtu")
    options = ["--partitions", "4", "--iterations", "2", "--edge-length-factor", "0.25"]
    expect_early_error(cgmesh, scratch, "two iterations over the limit",
                       ["refine", cube, out, *options, "--max-cells", "5000"], out, 1,
                       "more than the limit of 5000")
    result = run(cgmesh, "refine", cube, out, *options, "--max-cells", str(64 * 162))
    check(result.returncode == 0, "a run making exactly --max-cells tets was refused: "
          + result.stderr)


# Reads a .vtu with ParaView's reader; prints a digest of its points, cells and arrays, and
# whether VTK's own writer, with the same settings, writes the same file (up to arrays written as
# empty elements rather than self-closing ones, the trace of cached ranges).
READ_BACK = """import hashlib, re, sys
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader, vtkXMLUnstructuredGridWriter
name, compressor, copy = sys.argv[1:4]
reader = vtkXMLUnstructuredGridReader()
reader.SetFileName(name)
reader.Update()
grid = reader.GetOutput()
content = hashlib.sha256()
content.update(vtk_to_numpy(grid.GetPoints().GetData()).tobytes())
content.update(vtk_to_numpy(grid.GetCells().GetConnectivityArray()).tobytes())
content.update(vtk_to_numpy(grid.GetCellTypesArray()).tobytes())
for data in (grid.GetPointData(), grid.GetCellData()):
    for index in range(data.GetNumberOfArrays()):
        content.update(data.GetArrayName(index).encode())
        content.update(vtk_to_numpy(data.GetArray(index)).tobytes())
writer = vtkXMLUnstructuredGridWriter()
writer.SetInputData(grid)
writer.SetFileName(copy)
writer.SetDataModeToAppended()
writer.EncodeAppendedDataOff()
writer.SetHeaderTypeToUInt64()
getattr(writer, "SetCompressorTypeTo" + compressor)()
if compressor == "ZLib":
    writer.SetCompressionLevel(1)
writer.Write()
with open(name, "rb") as first, open(copy, "rb") as second:
    ours = re.sub(rb">\\n *</DataArray>", b"/>", first.read())
    same = ours == second.read()
print(grid.GetNumberOfCells(), content.hexdigest(), same)
"""

COMPRESSORS = {"none": ("None", None), "lz4": ("LZ4", b"vtkLZ4DataCompressor"),
               "zlib": ("ZLib", b"vtkZLibDataCompressor")}


def test_compression(cgmesh, scratch):
    """Every --compression reads back in ParaView's reader with the same mesh and arrays, as
    appended raw data; the file is what VTK's writer makes of the same grid, and the same for 1
    and 2 threads."""
    cube = os.path.join(scratch, "cube.vtu")
    contents = {}
    for name, (compressor, header) in COMPRESSORS.items():
        outputs = []
        for threads in ("1", "2"):
            refined = os.path.join(scratch, "compressed-%s-%s.vtu" % (name, threads))
            result = run(cgmesh, "refine", cube, refined, "--partitions", "4", "--iterations", "2",
                         "--edge-length-factor", "0.25", "--threads", threads,
                         "--compression", name)
            check(result.returncode == 0, "--compression %s: %s" % (name, result.stderr))
            if result.returncode != 0:
                return
            with open(refined, "rb") as handle:
                outputs.append(handle.read())
        check(outputs[0] == outputs[1], "--compression %s: 1 and 2 threads differ" % name)
        head = outputs[0][:400]
        check(b'header_type="UInt64"' in head, name + ": not a 64-bit header")
        check((header in head) if header else b"compressor=" not in head,
              name + ": compressor attribute: %r" % head)
        check(b'<AppendedData encoding="raw">' in outputs[0], name + ": not appended raw data")
        read = subprocess.run([sys.executable, "-c", READ_BACK, refined, compressor,
                               os.path.join(scratch, "vtk-%s.vtu" % name)],
                              capture_output=True, text=True)
        check(read.returncode == 0, name + ": ParaView's reader failed: " + read.stderr)
        if read.returncode != 0:
            continue
        cells, content, same = read.stdout.split()
        check(cells == str(64 * 162), "%s: read %s cells" % (name, cells))
        check(same == "True", name + ": not the file VTK's writer makes of the same grid")
        contents[name] = content
    check(len(set(contents.values())) == 1, "the compressions read back differently: %s" % contents)
    default = os.path.join(scratch, "compressed-default.vtu")
    stats = os.path.join(scratch, "compressed-default.json")
    run(cgmesh, "refine", cube, default, "--partitions", "4", "--iterations", "2",
        "--edge-length-factor", "0.25", "--stats", stats)
    check(digest(default) == digest(os.path.join(scratch, "compressed-none-1.vtu")),
          "the default is not none")
    with open(stats) as handle:
        check(json.load(handle).get("compression") == "none", "stats lack the compression")
    out = os.path.join(scratch, "compressed.vtk")
    expect_early_error(cgmesh, scratch, "compressed legacy file",
                       ["refine", cube, out, "--compression", "lz4"], out, 2,
                       "--compression lz4 needs a .vtu output")
    check(run(cgmesh, "refine", cube, out, "--compression", "none").returncode == 0,
          "--compression none with a .vtk output")
    generated = os.path.join(scratch, "generated-zlib.vtu")
    check(run(cgmesh, "generate", "cube", "2", generated, "--compression", "zlib").returncode == 0
          and b"vtkZLibDataCompressor" in open(generated, "rb").read(400),
          "generate --compression zlib")
    result = run(cgmesh, "tetgen", cube, os.path.join(scratch, "tetgen-none.vtu"), "--max-volume",
                 "0.01", "--compression", "none")
    check(result.returncode == 0, "tetgen --compression none: " + result.stderr)



def test_meshio_reads_outputs(cgmesh, scratch):
    """meshio (Debian's python3-meshio) reads the CLI's default (uncompressed) and zlib .vtu files
    and legacy .vtk files with every array, and the three give the same points and values (only
    LZ4 is beyond it). Text diagnostics and material names are written only when asked for."""
    import meshio
    finfet = os.path.join(scratch, "meshio-finfet.vtu")
    check(run(cgmesh, "generate", "finfet-grid", finfet, "--cells", "3000").returncode == 0,
          "generate finfet-grid")
    plain = os.path.join(scratch, "meshio-refined.vtu")
    check(run(cgmesh, "refine", finfet, plain, "--partitions", "16").returncode == 0,
          "refine with the default compression")
    outputs = {"vtu none": os.path.join(scratch, "meshio-refined-none.vtu"),
               "vtu zlib": os.path.join(scratch, "meshio-refined-zlib.vtu"),
               "vtk": os.path.join(scratch, "meshio-refined.vtk")}
    read = {}
    cell_arrays = {"Material", "PartitionId", "ColorId", "NearFormerInterface", "EdgeRatio",
                   "MinDihedralAngle"}
    for kind, path in outputs.items():
        stats = path + ".json"
        extra = ["--compression", "zlib"] if kind == "vtu zlib" else []
        result = run(cgmesh, "refine", finfet, path, "--region-array", "Material",
                     "--partitions", "16", "--stats", stats, *extra)
        check(result.returncode == 0, "refine for meshio (%s): %s" % (kind, result.stderr))
        if result.returncode != 0:
            continue
        with open(stats) as handle:
            cells = json.load(handle)["output"]["cells"]
        try:
            mesh = meshio.read(path)
        except Exception as error:  # meshio raises its own and numpy's errors
            check(False, "meshio cannot read the %s output: %s" % (kind, error))
            continue
        check(sum(len(block.data) for block in mesh.cells if block.type == "tetra") == cells,
              "meshio (%s): wrong tet count" % kind)
        read[kind] = mesh
        check(cell_arrays <= set(mesh.cell_data),
              "meshio (%s): cell arrays %s" % (kind, sorted(mesh.cell_data)))
        if kind == "vtk":
            continue  # meshio's legacy reader drops a dataset's FIELD block
        for name in ("MethodIndex", "ColoringAlgorithmIndex", "NumberOfColors", "IterationsRun"):
            check(name in mesh.field_data, "meshio (%s): field data %s missing" % (kind, name))
    if len(read) == len(outputs):
        import numpy
        reference = read["vtu zlib"]
        for kind, mesh in read.items():
            check(numpy.array_equal(mesh.points, reference.points) and
                  all(numpy.array_equal(mesh.cell_data[name][0], reference.cell_data[name][0])
                      for name in ("Material", "PartitionId", "MinDihedralAngle")),
                  "meshio reads other values from the %s output than from the zlib one" % kind)
    named = os.path.join(scratch, "meshio-named.vtu")
    diagnosed = os.path.join(scratch, "meshio-diagnostics.vtu")
    run(cgmesh, "generate", "finfet-grid", named, "--cells", "3000", "--material-names")
    run(cgmesh, "refine", finfet, diagnosed, "--partitions", "16", "--diagnostics")
    for path, name in ((finfet, None), (named, b'Name="MaterialNames"'),
                       (plain, None), (diagnosed, b'Name="Method"')):
        with open(path, "rb") as handle:
            content = handle.read()
        if name:
            check(name in content, "%s lacks %s" % (path, name))
        else:
            check(b'type="String"' not in content, "%s holds a string array" % path)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cgmesh", required=True)
    parser.add_argument("--scratch", required=True)
    options = parser.parse_args()
    shutil.rmtree(options.scratch, ignore_errors=True)
    os.makedirs(options.scratch)
    test_help(options.cgmesh)
    test_generate_refine_check(options.cgmesh, options.scratch)
    test_colorings(options.cgmesh, options.scratch)
    test_partition_by_region(options.cgmesh, options.scratch)
    test_delaunay(options.cgmesh, options.scratch)
    test_improvement_options(options.cgmesh, options.scratch)
    test_tetgen(options.cgmesh, options.scratch)
    test_errors(options.cgmesh, options.scratch)
    check(run(options.cgmesh, "generate", "cube", "10",
              os.path.join(options.scratch, "cube10.vtu")).returncode == 0, "generate cube 10")
    test_stats_checked_first(options.cgmesh, options.scratch)
    test_output_is_not_input(options.cgmesh, options.scratch)
    test_option_values(options.cgmesh, options.scratch)
    test_nothing_refined(options.cgmesh, options.scratch)
    test_region_array_named(options.cgmesh, options.scratch)
    test_material_labels_by_default(options.cgmesh, options.scratch)
    test_point_labels(options.cgmesh, options.scratch)
    test_size_forecast(options.cgmesh, options.scratch)
    test_compression(options.cgmesh, options.scratch)
    test_meshio_reads_outputs(options.cgmesh, options.scratch)
    if FAILURES:
        print("%d checks failed" % len(FAILURES), file=sys.stderr)
        return 1
    print("all command-line checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
