// cgmesh generate cube N OUT.vtu | finfet OUT.vtu [--cells N]: benchmark meshes.
#include "Commands.h"

#include "CommandLine.h"
#include "CubeGenerator.h"
#include "FinFetGenerator.h"
#include "MeshFiles.h"
#include "cgmeshVTKConversion.h"

#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <iostream>

namespace cgmesh
{

namespace
{

void printGenerateUsage()
{
  std::cout
    << "usage: cgmesh generate cube N OUT.vtu [--compression NAME]\n"
       "       cgmesh generate finfet OUT.vtu [--cells N] [--material-names] [--compression NAME]\n"
       "       cgmesh generate finfet-grid OUT.vtu [--cells N] [--material-names]\n"
       "                                   [--compression NAME]\n"
       "\n"
       "cube:        the unit cube cut into N^3 hexahedra of 6 positively oriented tetrahedra\n"
       "             each (N=10: the 6,000-tet Small cube, N=25: the 93,750-tet Big cube).\n"
       "finfet:      a double-gate FinFET (nm units) meshed by TetGen from a piecewise linear\n"
       "             complex of its material boxes, with about N quality tetrahedra (default\n"
       "             837584; within 5% for large meshes). Cell array 'Material' holds the\n"
       "             material ids 0 to 8: substrate, buried oxide, fin channel, source, drain,\n"
       "             gate oxide, gate, spacer, isolation oxide. --material-names also writes\n"
       "             them as the string array 'MaterialNames' in the field data (meshio does\n"
       "             not read string arrays, so they are left out by default).\n"
       "finfet-grid: the same device as Kuhn tetrahedra on a graded structured grid whose\n"
       "             planes follow every material boundary.\n"
       "OUT may be .vtu or .vtk.\n"
       "\n"
    << compressionHelp();
}

} // namespace

int runGenerateCommand(const std::vector<std::string>& commandArguments)
{
  GenerateArguments arguments;
  const int early =
    startCommand(commandArguments, printGenerateUsage, parseGenerateArguments, arguments);
  if (early >= 0)
  {
    return early;
  }
  Status status = checkOutputFileName(arguments.outputFile);
  if (!status.ok())
    return reportError(status.message());
  TetMesh mesh;
  const bool isFinFet = arguments.shape != "cube";
  if (arguments.shape == "finfet")
  {
    status = generateFinFetWithTetGen(arguments.targetCells, mesh);
  }
  else
  {
    status = isFinFet ? generateFinFet(arguments.targetCells, mesh)
                      : generateKuhnCube(arguments.cellsPerSide, mesh);
  }
  if (!status.ok())
    return reportError(status.message());
  vtkNew<vtkUnstructuredGrid> grid;
  convertToUnstructuredGrid(mesh, grid, "Material");
  if (isFinFet && arguments.materialNames)
  {
    vtkNew<vtkStringArray> names;
    names->SetName("MaterialNames");
    for (const std::string& name : finFetMaterialNames())
    {
      names->InsertNextValue(name);
    }
    grid->GetFieldData()->AddArray(names);
  }
  status = writeUnstructuredGrid(grid, arguments.outputFile, arguments.compression);
  if (!status.ok())
    return reportError(status.message());
  std::cout << "wrote " << arguments.outputFile << ": " << mesh.numberOfPoints() << " points, "
            << mesh.numberOfTets() << " tetrahedra\n";
  return 0;
}

} // namespace cgmesh
