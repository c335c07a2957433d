"""Drives the cgmesh executable: generate, refine (XML and legacy files, --stats, every colouring,
partitioning by region, the Delaunay method, quality improvement options and the quality summary),
the serial tetgen baseline, check, --help, and the error paths (one line on stderr, non-zero exit,
no output file)."""
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
                 "--max-cells"):
        check(text in refine_help, "refine --help does not mention " + text)
    tetgen_help = run(cgmesh, "tetgen", "--help").stdout
    for text in ("--max-volume", "--radius-edge-ratio", "--region-array", "--stats", "rQq"):
        check(text in tetgen_help, "tetgen --help does not mention " + text)


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
    for phase in ("partition", "graph", "color", "adapt", "heal", "merge", "quality", "total"):
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
    result = run(cgmesh, "check", refined, "--region-array", "Material")
    check(result.returncode == 0, "check the refined FinFET: " + result.stdout)


def region_volumes(cgmesh, mesh):
    """{region id: volume} from `cgmesh check --region-array Material`, and the exit status."""
    result = run(cgmesh, "check", mesh, "--region-array", "Material")
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
    check(improvement["seconds"] == improved["seconds"]["improve"]
          and 0 < improvement["shareOfTotal"] < 1, "improve seconds and share in stats")
    check_quality_summary(improved, refined, "improved")
    check(runs["passes-3"][0]["improvement"]["passes"] == 3, "--improve-passes 3 in stats")
    for name in ("passes-0", "not-improved"):
        statistics, _, output = runs[name]
        figures = statistics["improvement"]
        check(figures["edgeRemovals"] == figures["faceSwaps"] == figures["vertexMoves"] == 0,
              name + ": improvement counts are not 0")
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
    """The serial baseline on the FinFET: valid, every region's volume kept, quality arrays and
    stats written."""
    finfet = os.path.join(scratch, "finfet.vtu")
    refined = os.path.join(scratch, "finfet-tetgen.vtu")
    stats = os.path.join(scratch, "finfet-tetgen.json")
    before, _ = region_volumes(cgmesh, finfet)
    volume = sum(before.values())
    result = run(cgmesh, "tetgen", finfet, refined, "--max-volume", str(0.3 * volume / 3000),
                 "--radius-edge-ratio", "2", "--region-array", "Material", "--stats", stats)
    check(result.returncode == 0, "tetgen: " + result.stderr)
    if result.returncode != 0:
        return
    check("tetgen" in result.stdout and "rQq2a" in result.stdout, "tetgen table: " + result.stdout)
    with open(stats) as handle:
        statistics = json.load(handle)
    for phase in ("tetgen", "quality", "read", "write", "total"):
        check(phase in statistics["seconds"], "tetgen stats lack seconds of " + phase)
    check(statistics["output"]["cells"] > 2 * statistics["input"]["cells"], "tetgen: no refinement")
    check(statistics["tetgenPoints"] > 0 and statistics["switches"].startswith("rQq2a"),
          "tetgen stats: points/switches")
    after, status = region_volumes(cgmesh, refined)
    check(status == 0, "check the TetGen-refined FinFET")
    check(before.keys() == after.keys() and all(
        abs(after[region] - volume) <= 1e-9 * volume for region, volume in before.items()),
        "TetGen region volumes %s != input %s" % (after, before))
    reader_check = subprocess.run(
        [sys.executable, "-c", "import sys\nfrom vtkmodules.vtkIOXML import "
         "vtkXMLUnstructuredGridReader\nr = vtkXMLUnstructuredGridReader()\n"
         "r.SetFileName(sys.argv[1])\nr.Update()\ncd = r.GetOutput().GetCellData()\n"
         "sys.exit(0 if cd.GetArray('EdgeRatio') and cd.GetArray('MinDihedralAngle') "
         "and cd.GetArray('Material') else 1)", refined], capture_output=True, text=True)
    check(reader_check.returncode == 0, "tetgen output lacks EdgeRatio/MinDihedralAngle/Material")


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
    if FAILURES:
        print("%d checks failed" % len(FAILURES), file=sys.stderr)
        return 1
    print("all command-line checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
