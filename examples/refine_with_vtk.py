"""Refine a tetrahedral mesh with the wrapped VTK module, without ParaView's proxies.

    PYTHONPATH=build/lib/python3.11/site-packages /usr/bin/python3 \
        examples/refine_with_vtk.py Data/finfet-small.vtu finfet-refined.vtu --region-array Material

Works the same under pvbatch. After `cmake --install`, PYTHONPATH is
<prefix>/lib/python3.11/site-packages.
"""
import argparse

from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader, vtkXMLUnstructuredGridWriter

from cgmesh import vtkCoarseGrainedMeshAdaptation


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("input", help="tetrahedral mesh (.vtu)")
    parser.add_argument("output", help="refined mesh (.vtu)")
    parser.add_argument("--region-array", help="cell array of material ids")
    parser.add_argument("--partitions", type=int, default=64)
    parser.add_argument("--iterations", type=int, default=1)
    parser.add_argument("--edge-length-factor", type=float, default=0.5)
    parser.add_argument("--threads", type=int, default=0, help="0: all cores")
    options, _ = parser.parse_known_args()

    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(options.input)

    adaptation = vtkCoarseGrainedMeshAdaptation()
    adaptation.SetInputConnection(reader.GetOutputPort())
    adaptation.SetNumberOfPartitions(options.partitions)
    adaptation.SetNumberOfIterations(options.iterations)
    adaptation.SetEdgeLengthFactor(options.edge_length_factor)
    adaptation.SetNumberOfThreads(options.threads)
    if options.region_array:
        adaptation.SetRegionArrayName(options.region_array)

    writer = vtkXMLUnstructuredGridWriter()
    writer.SetInputConnection(adaptation.GetOutputPort())
    writer.SetFileName(options.output)
    if not writer.Write():
        raise SystemExit("could not write " + options.output)

    refined = adaptation.GetOutput()
    field = refined.GetFieldData()
    print("%d -> %d tets, %d colours, %.2f s" % (
        reader.GetOutput().GetNumberOfCells(), refined.GetNumberOfCells(),
        field.GetArray("NumberOfColors").GetValue(0), field.GetArray("TotalSeconds").GetValue(0)))


if __name__ == "__main__":
    main()
