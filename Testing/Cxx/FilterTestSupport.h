// Shared helpers of the filter tests: test meshes with known data, running the filter, checks.
#ifndef cgmesh_FilterTestSupport_h
#define cgmesh_FilterTestSupport_h

#include "Validation/MeshValidation.h"
#include "vtkCoarseGrainedMeshAdaptation.h"
#include "vtkSmartPointer.h"

#include <iostream>
#include <string>

class vtkUnstructuredGrid;

namespace cgmesh_test
{

// Counts failed checks; main() returns non-zero when any failed.
extern int FailureCount;

#define CGMESH_CHECK(condition, message)                                                           \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " << #condition << " -- "       \
                << message << std::endl;                                                           \
      ++cgmesh_test::FailureCount;                                                                 \
    }                                                                                              \
  } while (false)

// The Kuhn cube (N^3 hexahedra x 6 tets) with the test arrays:
//   point "LinearField" (double) = x + 2y + 3z,
//   cell "ParentId" (vtkIdType) = input cell id,
//   cell "Material" (float) = 1 + (cell lies in the upper half in z), for RegionArrayName.
vtkSmartPointer<vtkUnstructuredGrid> makeCubeWithTestArrays(int cellsPerSide);

struct FilterSettings
{
  int numberOfPartitions = 1;
  int numberOfIterations = 2;
  int method = vtkCoarseGrainedMeshAdaptation::TEMPLATE;
  double edgeLengthFactor = 0.25; // splits every edge of a Kuhn cube in both iterations
  double volumeFactor = 0.1;      // Delaunay
  double radiusEdgeRatio = 2.0;   // Delaunay
  int numberOfThreads = 1;
  std::string regionArrayName;
  int coloringAlgorithm = vtkCoarseGrainedMeshAdaptation::GREEDY_LEAST_USED;
  bool partitionByRegion = false;
  int partitionsPerRegion = 1;
  bool improveQuality = true;
  bool improveInput = true;
  int improvementPasses = 2;
};

// Runs vtkCoarseGrainedMeshAdaptation; returns null (and counts a failure) when it fails.
vtkSmartPointer<vtkUnstructuredGrid> runFilter(
  vtkUnstructuredGrid* input, const FilterSettings& settings);

// Conformity, orientation, no degenerate/duplicate/unused points, conserved volume and boundary
// area (1e-9 relative) against the input.
void checkConformity(vtkUnstructuredGrid* input, vtkUnstructuredGrid* output);

// LinearField exact on every output point, every child inside its ParentId tet with the children's
// volumes summing to the parent's, Material copied, output arrays present and in range, colour
// populations matching the PartitionId and ColorId arrays.
void checkDataTransfer(vtkUnstructuredGrid* input, vtkUnstructuredGrid* output);

// The parts of checkDataTransfer that hold for any method (a Delaunay child need not lie inside
// the parent tet it is attributed to): LinearField exact on every output point, and the output
// arrays and field data present and consistent.
void checkLinearField(vtkUnstructuredGrid* output);
void checkOutputArrays(vtkUnstructuredGrid* output);

// Validity figures of `grid`, with region volumes and the region-interface area when
// `regionArrayName` is not empty.
cgmesh::MeshReport inspectGrid(vtkUnstructuredGrid* grid, const std::string& regionArrayName);

// Points, connectivity, cell types and every point and cell array bit-identical (arrays that are
// not numeric, such as vtkStringArray, value by value).
bool identicalGrids(
  vtkUnstructuredGrid* first, vtkUnstructuredGrid* second, std::string& difference);

// The single value of a numeric field-data array; -1 (and a failed check) when it is missing.
double fieldValue(vtkUnstructuredGrid* output, const char* name);

} // namespace cgmesh_test

#endif
