"""The pipeline of a ParaView user who refines a mesh under MPI (run by `mpiexec pvbatch --mpi`):
reader, optionally RedistributeDataSet, the filter, and the parallel .pvtu writer, which writes
one piece per process. TestDistributed drives it and checks the pieces."""
import argparse

from paraview import simple  # its proxy constructors exist once the session does: simple.Name


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--input", required=True)
    parser.add_argument("--output", required=True, help=".pvtu file")
    parser.add_argument("--redistribute", action="store_true")
    parser.add_argument("--ghost-level", type=int, default=0)
    parser.add_argument("--set", nargs="*", default=[], metavar="PROPERTY=VALUE")
    options = parser.parse_args()
    simple.LoadPlugin(options.plugin, ns=globals())
    source = simple.OpenDataFile(options.input)  # a .pvtu's pieces go to the processes
    if options.redistribute:
        source = simple.RedistributeDataSet(Input=source)
    adaptation = CoarseGrainedMeshAdaptation(Input=source)  # noqa: F821 (from LoadPlugin)
    for assignment in options.set:
        name, value = assignment.split("=", 1)
        try:
            value = float(value) if "." in value else int(value)
        except ValueError:
            pass
        setattr(adaptation, name, value)
    writer = simple.XMLPUnstructuredGridWriter(Input=adaptation, FileName=options.output,
                                        GhostLevel=options.ghost_level)
    writer.UpdatePipeline()


if __name__ == "__main__":
    main()
