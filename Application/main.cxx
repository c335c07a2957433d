// cgmesh: command-line driver of the coarse-grained mesh adaptation (same library as the plugin).
#include "Commands.h"

#include <iostream>
#include <string>
#include <vector>

namespace
{

void printUsage(std::ostream& stream)
{
  stream << "usage: cgmesh <command> [arguments]\n"
            "\n"
            "commands:\n"
            "  refine IN OUT [options]   refine a tetrahedral mesh (VTK, Gmsh, Medit, Exodus II\n"
            "                            or TetGen files)\n"
            "  generate cube N OUT.vtu | finfet OUT.vtu | finfet-grid OUT.vtu\n"
            "                            write a benchmark mesh\n"
            "  tetgen IN OUT --max-volume V [options]\n"
            "                            serial TetGen on the whole mesh (Delaunay baseline)\n"
            "  check IN [options]        report conformity, orientation, volume and areas\n"
            "\n"
            "Run 'cgmesh <command> --help' for the options of a command.\n"
            "\n"
            "exit status:\n"
            "  0  success (check: the mesh is valid)\n"
            "  1  failure: bad input, failed refinement, unwritable output (one line on stderr;\n"
            "     no output file is left behind); check: the mesh is not valid\n"
            "  2  usage error: unknown command or option, bad value\n"
            "\n"
            "refine shows a progress bar on stderr when stderr is a terminal.\n";
}

} // namespace

int cgmesh::reportError(const std::string& message)
{
  std::cerr << "cgmesh: error: " << message << "\n";
  return cgmesh::FailureExitStatus;
}

int cgmesh::reportFailure(const Status& status)
{
  reportError(status.message());
  return status.kind() == ErrorKind::InvalidOption ? UsageErrorExitStatus : FailureExitStatus;
}

int main(int argc, char* argv[])
{
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  if (arguments.empty())
  {
    printUsage(std::cerr);
    return cgmesh::UsageErrorExitStatus;
  }
  const std::string& command = arguments.front();
  const std::vector<std::string> commandArguments(arguments.begin() + 1, arguments.end());
  if (command == "-h" || command == "--help" || command == "help")
  {
    printUsage(std::cout);
    return 0;
  }
  if (command == "refine")
    return cgmesh::runRefineCommand(commandArguments);
  if (command == "generate")
    return cgmesh::runGenerateCommand(commandArguments);
  if (command == "check")
    return cgmesh::runCheckCommand(commandArguments);
  if (command == "tetgen")
    return cgmesh::runTetGenCommand(commandArguments);
  cgmesh::reportError("unknown command '" + command + "' (try cgmesh --help)");
  return cgmesh::UsageErrorExitStatus;
}
