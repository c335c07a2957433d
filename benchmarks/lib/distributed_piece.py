"""One process's share of a distributed run (`mpiexec -n R pvbatch --mpi --symmetric`): the
reader, RedistributeDataSet when R > 1, the filter; each process writes its piece's figures to
FIGURES/piece-<rank>.json (their stdout lines would interleave). Run by benchmarks/distributed."""
import argparse
import json
import os
import time

from paraview import simple
from vtkmodules.vtkParallelCore import vtkMultiProcessController


def field_value(data, name):
    array = data.GetFieldData().GetArray(name)
    return array.GetValue(0) if array is not None else None


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--input", required=True)
    parser.add_argument("--figures", required=True, help="folder for piece-<rank>.json")
    parser.add_argument("--set", nargs="*", default=[], metavar="PROPERTY=VALUE")
    options = parser.parse_args()
    controller = vtkMultiProcessController.GetGlobalController()
    processes = controller.GetNumberOfProcesses() if controller else 1
    simple.LoadPlugin(options.plugin, ns=globals())
    source = simple.XMLUnstructuredGridReader(FileName=[options.input])
    start = time.monotonic()
    source.UpdatePipeline()
    read_seconds = time.monotonic() - start
    start = time.monotonic()
    if processes > 1:
        source = simple.RedistributeDataSet(Input=source)
        source.UpdatePipeline()
    redistribute_seconds = time.monotonic() - start
    adaptation = CoarseGrainedMeshAdaptation(Input=source)  # noqa: F821 (from LoadPlugin)
    for assignment in options.set:
        name, value = assignment.split("=", 1)
        try:
            value = float(value) if "." in value else int(value)
        except ValueError:
            pass
        setattr(adaptation, name, value)
    start = time.monotonic()
    adaptation.UpdatePipeline()
    filter_wall = time.monotonic() - start
    piece = adaptation.GetClientSideObject().GetOutputDataObject(0)
    figures = {"rank": controller.GetLocalProcessId() if controller else 0,
               "processes": processes, "readSeconds": read_seconds,
               "redistributeSeconds": redistribute_seconds, "filterWallSeconds": filter_wall,
               "cells": piece.GetNumberOfCells(), "points": piece.GetNumberOfPoints()}
    for name in ("TotalSeconds", "AdaptSeconds", "ImproveSeconds", "PartitionSeconds",
                 "MergeSeconds", "QualitySeconds", "ProcessSharedPoints", "ProcessExchangeBytes",
                 "ProcessNumberingSeconds", "GhostCellSeconds", "NumberOfThreads", "NumberOfPartitions"):
        figures[name] = field_value(piece, name)
    with open(os.path.join(options.figures, "piece-%d.json" % figures["rank"]), "w") as handle:
        json.dump(figures, handle)


if __name__ == "__main__":
    main()
