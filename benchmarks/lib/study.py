"""The study's cases, their reference parameters and the partition count, shared by
benchmarks/run and benchmarks/strong-scaling."""

PARTITIONS = 1024
COLORINGS = ("greedy", "greedy-lu")
SIMULATED_THREADS = (1, 2, 4, 8, 16, 32, 64)

# The benchmark cases and their reference parameters.
CASES = {
    "small": {"title": "Small cube", "generate": ["cube", "10"], "regionArray": None,
              "template": {"iterations": 2, "edgeLengthFactor": 0.25},
              "delaunay": {"iterations": 2, "volumeFactor": 0.01}},
    "big": {"title": "Big cube", "generate": ["cube", "25"], "regionArray": None,
            "template": {"iterations": 2, "edgeLengthFactor": 0.25},
            # Reference: 0.01, which gives 19.7 M tets here; one 2-thread
            # run takes 210 s, the four runs about 21 minutes and the study about 39 minutes on
            # 2 cores. 0.04 gives 5.3 M tets, a count comparable with the template method's 6 M.
            "delaunay": {"iterations": 2, "volumeFactor": 0.04}},
    "finfet": {"title": "FinFET", "generate": ["finfet"], "cells": None,
               "regionArray": "Material",
               "template": {"iterations": 1, "edgeLengthFactor": 0.5},
               "delaunay": {"iterations": 1, "volumeFactor": 0.13}},
}


def refine_command(cgmesh, case, method, coloring, threads, source, output, stats_file):
    """`cgmesh refine` of a case with the study's parameters for `method`."""
    parameters = case[method]
    command = [cgmesh, "refine", source, output, "--method", method,
               "--partitions", str(PARTITIONS), "--iterations", str(parameters["iterations"]),
               "--coloring", coloring, "--threads", str(threads), "--stats", stats_file]
    if method == "template":
        command += ["--edge-length-factor", repr(parameters["edgeLengthFactor"])]
    else:
        command += ["--volume-factor", repr(parameters["volumeFactor"])]
    if case["regionArray"]:
        command += ["--region-array", case["regionArray"]]
    return command


def tetgen_command(cgmesh, case, source, output, volume_bound, stats_file):
    """Serial TetGen (`cgmesh tetgen`) on a case's input with an absolute volume bound."""
    command = [cgmesh, "tetgen", source, output, "--max-volume", repr(volume_bound),
               "--stats", stats_file]
    if case["regionArray"]:
        command += ["--region-array", case["regionArray"]]
    return command
