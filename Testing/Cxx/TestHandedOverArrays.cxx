// VTK arrays that take over a std::vector's storage (cgmeshHandedOverArrays.h): the values are the
// vector's, the storage is freed exactly when VTK lets go of it (array deleted, buffer reallocated,
// shallow copies released), and the filter's output leaves nothing behind once it is deleted.
#include "FilterTestSupport.h"

#include "CubeGenerator.h"
#include "cgmeshHandedOverArrays.h"
#include "cgmeshVTKConversion.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <iostream>
#include <numeric>
#include <vector>

namespace
{

using cgmesh::handedOverStorageCount;

// The grid holds exactly the mesh's points, tets and regions.
void checkGridHoldsMesh(vtkUnstructuredGrid* grid, const cgmesh::TetMesh& mesh)
{
  CGMESH_CHECK(grid->GetNumberOfPoints() == mesh.numberOfPoints(), "point count");
  CGMESH_CHECK(grid->GetNumberOfCells() == mesh.numberOfTets(), "cell count");
  for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p)
  {
    double xyz[3];
    grid->GetPoint(p, xyz);
    for (int k = 0; k < 3; ++k)
    {
      CGMESH_CHECK(xyz[k] == mesh.point(p)[k], "point " << p << " moved");
    }
  }
  vtkNew<vtkIdList> corners;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    grid->GetCellPoints(c, corners);
    CGMESH_CHECK(corners->GetNumberOfIds() == 4 && grid->GetCellType(c) == VTK_TETRA,
      "cell " << c << " is not a tet");
    for (int k = 0; k < 4 && k < corners->GetNumberOfIds(); ++k)
    {
      CGMESH_CHECK(corners->GetId(k) == mesh.tets[c][k], "cell " << c << " corner " << k);
    }
  }
  vtkDataArray* regions = grid->GetCellData()->GetArray("Region");
  CGMESH_CHECK(regions && regions->GetNumberOfTuples() == mesh.numberOfTets(), "regions");
  for (vtkIdType c = 0; regions && c < regions->GetNumberOfTuples(); ++c)
  {
    CGMESH_CHECK(regions->GetComponent(c, 0) == mesh.regions[c], "region of cell " << c);
  }
}

void testConvertedMesh()
{
  cgmesh::TetMesh mesh;
  CGMESH_CHECK(cgmesh::generateKuhnCube(3, mesh).ok(), "cube");
  mesh.regions.resize(mesh.tets.size());
  std::iota(mesh.regions.begin(), mesh.regions.end(), 7);
  const std::size_t before = handedOverStorageCount();

  cgmesh::TetMesh taken = mesh;
  const double* coordinates = taken.coordinates.data();
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  cgmesh::convertToUnstructuredGrid(std::move(taken), grid, "Region");
  CGMESH_CHECK(taken.numberOfPoints() == 0 && taken.numberOfTets() == 0 && taken.regions.empty(),
    "the moved mesh is not left empty");
  CGMESH_CHECK(handedOverStorageCount() == before + 3,
    "points, connectivity and regions are not all handed over");
  CGMESH_CHECK(grid->GetPoints()->GetData()->GetVoidPointer(0) == coordinates,
    "the points were copied, not taken over");
  checkGridHoldsMesh(grid, mesh);

  // A shallow copy shares the arrays: the storage stays while either grid holds them.
  auto shallow = vtkSmartPointer<vtkUnstructuredGrid>::New();
  shallow->ShallowCopy(grid);
  auto deep = vtkSmartPointer<vtkUnstructuredGrid>::New();
  deep->DeepCopy(grid);
  grid = nullptr;
  CGMESH_CHECK(handedOverStorageCount() == before + 3, "storage freed under a shallow copy");
  checkGridHoldsMesh(shallow, mesh);
  shallow = nullptr;
  CGMESH_CHECK(handedOverStorageCount() == before, "storage kept after both grids went");
  checkGridHoldsMesh(deep, mesh);

  // The copying overload leaves its mesh as it was.
  auto copied = vtkSmartPointer<vtkUnstructuredGrid>::New();
  cgmesh::convertToUnstructuredGrid(mesh, copied, "Region");
  CGMESH_CHECK(mesh.numberOfTets() > 0 && !mesh.regions.empty(), "the kept mesh was emptied");
  checkGridHoldsMesh(copied, mesh);
}

void testReallocation()
{
  const std::size_t before = handedOverStorageCount();
  std::vector<int> values(1000);
  std::iota(values.begin(), values.end(), -3);
  auto array = cgmesh::arrayTakingOver<vtkIntArray>(std::move(values));
  CGMESH_CHECK(values.empty(), "the vector was not taken");
  CGMESH_CHECK(array->GetNumberOfValues() == 1000 && array->GetValue(999) == 996, "values");
  CGMESH_CHECK(handedOverStorageCount() == before + 1, "not kept");
  // Growing past the vector's size makes VTK copy into a buffer of its own and give this one back.
  array->Resize(5000);
  array->InsertValue(4000, 11);
  CGMESH_CHECK(handedOverStorageCount() == before, "the old buffer was not given back");
  CGMESH_CHECK(
    array->GetValue(0) == -3 && array->GetValue(999) == 996 && array->GetValue(4000) == 11,
    "values lost in the reallocation");

  std::vector<double> none;
  auto empty = cgmesh::arrayTakingOver<vtkDoubleArray>(std::move(none), 3);
  CGMESH_CHECK(empty->GetNumberOfTuples() == 0 && empty->GetNumberOfComponents() == 3 &&
      handedOverStorageCount() == before,
    "an empty vector");
}

void testFilterOutput()
{
  const std::size_t before = handedOverStorageCount();
  {
    vtkSmartPointer<vtkUnstructuredGrid> input = cgmesh_test::makeCubeWithTestArrays(4);
    cgmesh_test::FilterSettings settings;
    settings.numberOfPartitions = 8;
    settings.numberOfThreads = 2;
    vtkSmartPointer<vtkUnstructuredGrid> output = cgmesh_test::runFilter(input, settings);
    CGMESH_CHECK(output != nullptr, "the filter failed");
    if (output)
    {
      CGMESH_CHECK(handedOverStorageCount() > before, "the filter's output copied its mesh");
      cgmesh_test::checkConformity(input, output);
      cgmesh_test::checkDataTransfer(input, output);
    }
  }
  CGMESH_CHECK(handedOverStorageCount() == before,
    handedOverStorageCount() - before << " buffers outlive the filter and its output");
}

} // namespace

int main()
{
  testConvertedMesh();
  testReallocation();
  testFilterOutput();
  if (cgmesh_test::FailureCount > 0)
  {
    std::cerr << cgmesh_test::FailureCount << " check(s) failed\n";
    return 1;
  }
  std::cout << "handed-over arrays: all checks passed\n";
  return 0;
}
