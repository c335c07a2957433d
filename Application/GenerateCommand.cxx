// cgmesh generate cube N OUT.vtu: benchmark meshes.
#include "Commands.h"

#include "CommandLine.h"
#include "CubeGenerator.h"
#include "MeshFiles.h"
#include "cgmeshVTKConversion.h"

#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

#include <iostream>

namespace cgmesh
{

namespace
{

void printGenerateUsage()
{
  std::cout << "usage: cgmesh generate cube N OUT.vtu\n"
               "\n"
               "Writes the unit cube cut into N^3 hexahedra of 6 positively oriented tetrahedra\n"
               "each (N=10: the 6,000-tet Small cube, N=25: the 93,750-tet Big cube).\n"
               "OUT may be .vtu or .vtk.\n";
}

} // namespace

int runGenerateCommand(const std::vector<std::string>& commandArguments)
{
  if (wantsHelp(commandArguments))
  {
    printGenerateUsage();
    return 0;
  }
  GenerateArguments arguments;
  Status status = parseGenerateArguments(commandArguments, arguments);
  if (!status.ok())
  {
    reportError(status.message());
    return UsageErrorExitStatus;
  }

  status = checkOutputFileName(arguments.outputFile);
  if (!status.ok())
    return reportError(status.message());
  TetMesh mesh;
  status = generateKuhnCube(arguments.cellsPerSide, mesh);
  if (!status.ok())
    return reportError(status.message());
  vtkNew<vtkUnstructuredGrid> grid;
  convertToUnstructuredGrid(mesh, grid);
  status = writeUnstructuredGrid(grid, arguments.outputFile);
  if (!status.ok())
    return reportError(status.message());
  std::cout << "wrote " << arguments.outputFile << ": " << mesh.numberOfPoints() << " points, "
            << mesh.numberOfTets() << " tetrahedra\n";
  return 0;
}

} // namespace cgmesh
