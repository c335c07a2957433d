// cgmesh check IN [--region-array NAME]: validity figures of a tetrahedral mesh.
#include "Commands.h"

#include "CommandLine.h"
#include "MeshFiles.h"
#include "Validation/MeshValidation.h"
#include "cgmeshTriangleCells.h"
#include "cgmeshVTKConversion.h"

#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

#include <iomanip>
#include <iostream>

namespace cgmesh
{

namespace
{

void printCheckUsage()
{
  std::cout
    << "usage: cgmesh check IN [--region-array NAME]\n"
       "\n"
       "Reports counts, inverted/degenerate tetrahedra, over-shared and misoriented faces,\n"
       "unused and duplicate points, volume, boundary area and (with a region array) the\n"
       "volume of each region. Triangles (tagged faces) must be faces of the tetrahedra.\n"
       "Exits with status 1 when the mesh is not valid.\n";
}

void printReport(const MeshReport& report, std::ostream& stream)
{
  stream << std::left << std::setprecision(12);
  const auto line = [&stream](const char* label) -> std::ostream&
  {
    return stream << std::setw(28) << label;
  };
  line("points") << report.numberOfPoints << "\n";
  line("tetrahedra") << report.numberOfTets << "\n";
  line("boundary faces") << report.boundaryFaces << "\n";
  line("interior faces") << report.interiorFaces << "\n";
  line("faces in 3+ tetrahedra") << report.overSharedFaces << "\n";
  line("misoriented face pairs") << report.misorientedFacePairs << "\n";
  line("inverted tetrahedra") << report.invertedTets << "\n";
  line("degenerate tetrahedra") << report.degenerateTets << "\n";
  line("repeated-corner tetrahedra") << report.repeatedCornerTets << "\n";
  line("unused points") << report.unusedPoints << "\n";
  line("duplicate points") << report.duplicatePoints << "\n";
  line("volume") << report.volume << "\n";
  line("boundary area") << report.boundaryArea << "\n";
  if (!report.regionVolumes.empty())
  {
    line("region interface faces") << report.regionInterfaceFaces << "\n";
    line("region interface area") << report.regionInterfaceArea << "\n";
    for (const auto& region : report.regionVolumes)
    {
      stream << "region " << std::setw(21) << region.first << region.second << "\n";
    }
  }
  stream << std::right;
}

} // namespace

int runCheckCommand(const std::vector<std::string>& commandArguments)
{
  CheckArguments arguments;
  const int early = startCommand(commandArguments, printCheckUsage, parseCheckArguments, arguments);
  if (early >= 0)
  {
    return early;
  }
  Status status = Status::success();
  vtkNew<vtkUnstructuredGrid> grid;
  status = readUnstructuredGrid(arguments.inputFile, grid);
  if (status.ok() && !arguments.regionArrayName.empty())
    status = checkRegionArray(grid, arguments.regionArrayName, arguments.inputFile);
  if (!status.ok())
    return reportError(status.message());
  const vtkIdType unsupported = countNonTetrahedra(grid, /*trianglesAccepted=*/true);
  if (unsupported > 0)
    return reportError(std::to_string(unsupported) +
      " cells are neither linear tetrahedra nor triangles: " +
      describeNonTetrahedra(grid, /*trianglesAccepted=*/true));
  // Triangles (tagged faces) are checked against the tets; the tets are inspected alone.
  vtkNew<vtkUnstructuredGrid> tets;
  TriangleCells triangles;
  separateTriangles(grid, tets, triangles);
  TetMesh mesh;
  status = convertToTetMesh(tets, arguments.regionArrayName, mesh);
  if (!status.ok())
    return reportError(status.message());

  const MeshReport report = inspectMesh(mesh);
  printReport(report, std::cout);
  const TaggedTriangleCheck triangleCheck = checkTaggedTriangles(mesh, triangles.triangles);
  if (!triangles.triangles.empty())
  {
    std::cout << std::left << std::setw(28) << "triangles" << triangles.triangles.size() << "\n"
              << std::setw(28) << "triangles on no tet face" << triangleCheck.notFaces << "\n"
              << std::right;
  }
  if (!report.isValid() || triangleCheck.notFaces > 0)
  {
    std::cout << "INVALID:\n" << report.describeProblems();
    if (triangleCheck.notFaces > 0)
      std::cout << "  " << triangleCheck.notFaces << " triangles are no face of a tetrahedron\n";
    return FailureExitStatus;
  }
  std::cout << "valid\n";
  return 0;
}

} // namespace cgmesh
