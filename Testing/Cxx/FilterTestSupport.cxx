#include "FilterTestSupport.h"

#include "CubeGenerator.h"
#include "Validation/MeshValidation.h"
#include "cgmeshVTKConversion.h"
#include "vtkCoarseGrainedMeshAdaptation.h"

#include "vtkAbstractArray.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkLongArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVariant.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <numeric>
#include <set>
#include <vector>

namespace cgmesh_test
{

int FailureCount = 0;

namespace
{

using Vector = std::array<double, 3>;

Vector pointOf(vtkUnstructuredGrid* grid, vtkIdType pointId)
{
  Vector point;
  grid->GetPoint(pointId, point.data());
  return point;
}

double signedVolume(const Vector& a, const Vector& b, const Vector& c, const Vector& d)
{
  const Vector u{ b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const Vector v{ c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  const Vector w{ d[0] - a[0], d[1] - a[1], d[2] - a[2] };
  return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
           u[2] * (v[0] * w[1] - v[1] * w[0])) /
    6.0;
}

std::array<Vector, 4> cellCorners(vtkUnstructuredGrid* grid, vtkIdType cellId)
{
  const vtkIdType* pointIds;
  vtkIdType count;
  grid->GetCellPoints(cellId, count, pointIds);
  return { pointOf(grid, pointIds[0]), pointOf(grid, pointIds[1]), pointOf(grid, pointIds[2]),
    pointOf(grid, pointIds[3]) };
}

// Smallest barycentric coordinate of `point` in `tet` (negative: outside).
double minimumBarycentric(const std::array<Vector, 4>& tet, const Vector& point)
{
  const double volume = signedVolume(tet[0], tet[1], tet[2], tet[3]);
  double minimum = 1.0;
  for (int corner = 0; corner < 4; ++corner)
  {
    std::array<Vector, 4> replaced = tet;
    replaced[corner] = point;
    minimum =
      std::min(minimum, signedVolume(replaced[0], replaced[1], replaced[2], replaced[3]) / volume);
  }
  return minimum;
}

bool relativelyEqual(double first, double second, double tolerance)
{
  return std::abs(first - second) <= tolerance * std::max(std::abs(first), std::abs(second));
}

bool sameBytes(vtkDataArray* first, vtkDataArray* second)
{
  if (!first || !second || first->GetDataType() != second->GetDataType() ||
    first->GetNumberOfTuples() != second->GetNumberOfTuples() ||
    first->GetNumberOfComponents() != second->GetNumberOfComponents())
  {
    return false;
  }
  const size_t bytes = static_cast<size_t>(first->GetNumberOfValues()) * first->GetDataTypeSize();
  return bytes == 0 || std::memcmp(first->GetVoidPointer(0), second->GetVoidPointer(0), bytes) == 0;
}

// Numeric arrays byte for byte, other arrays (strings, variants) value by value.
bool sameValues(vtkAbstractArray* first, vtkAbstractArray* second)
{
  auto* firstNumbers = vtkDataArray::SafeDownCast(first);
  auto* secondNumbers = vtkDataArray::SafeDownCast(second);
  if (firstNumbers || secondNumbers)
  {
    return sameBytes(firstNumbers, secondNumbers);
  }
  if (!first || !second || first->GetDataType() != second->GetDataType() ||
    first->GetNumberOfValues() != second->GetNumberOfValues() ||
    first->GetNumberOfComponents() != second->GetNumberOfComponents())
  {
    return false;
  }
  for (vtkIdType index = 0; index < first->GetNumberOfValues(); ++index)
  {
    if (!(first->GetVariantValue(index) == second->GetVariantValue(index)))
    {
      return false;
    }
  }
  return true;
}

bool sameArrays(vtkFieldData* first, vtkFieldData* second, std::string& difference)
{
  if (first->GetNumberOfArrays() != second->GetNumberOfArrays())
  {
    difference = "different numbers of arrays";
    return false;
  }
  for (int index = 0; index < first->GetNumberOfArrays(); ++index)
  {
    vtkAbstractArray* array = first->GetAbstractArray(index);
    const char* name = array ? array->GetName() : nullptr;
    if (!name || !sameValues(array, second->GetAbstractArray(name)))
    {
      difference = std::string("array ") + (name ? name : "(unnamed)") + " differs";
      return false;
    }
  }
  return true;
}

} // namespace

cgmesh::MeshReport inspectGrid(vtkUnstructuredGrid* grid, const std::string& regionArrayName)
{
  cgmesh::TetMesh mesh;
  cgmesh::Status status = cgmesh::convertToTetMesh(grid, regionArrayName, mesh);
  CGMESH_CHECK(status.ok(), status.message());
  return cgmesh::inspectMesh(mesh);
}

vtkSmartPointer<vtkUnstructuredGrid> makeCubeWithTestArrays(int cellsPerSide)
{
  cgmesh::TetMesh mesh;
  cgmesh::Status status = cgmesh::generateKuhnCube(cellsPerSide, mesh);
  CGMESH_CHECK(status.ok(), status.message());
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  cgmesh::convertToUnstructuredGrid(mesh, grid);

  vtkNew<vtkDoubleArray> linearField;
  linearField->SetName("LinearField");
  linearField->SetNumberOfValues(grid->GetNumberOfPoints());
  for (vtkIdType pointId = 0; pointId < grid->GetNumberOfPoints(); ++pointId)
  {
    const Vector point = pointOf(grid, pointId);
    linearField->SetValue(pointId, point[0] + 2 * point[1] + 3 * point[2]);
  }
  grid->GetPointData()->AddArray(linearField);

  vtkNew<vtkIdTypeArray> parentIds;
  parentIds->SetName("ParentId");
  vtkNew<vtkFloatArray> material;
  material->SetName("Material");
  parentIds->SetNumberOfValues(grid->GetNumberOfCells());
  material->SetNumberOfValues(grid->GetNumberOfCells());
  for (vtkIdType cellId = 0; cellId < grid->GetNumberOfCells(); ++cellId)
  {
    const auto corners = cellCorners(grid, cellId);
    const double centroidZ = (corners[0][2] + corners[1][2] + corners[2][2] + corners[3][2]) / 4;
    parentIds->SetValue(cellId, cellId);
    material->SetValue(cellId, centroidZ > 0.5 ? 2.0f : 1.0f);
  }
  grid->GetCellData()->AddArray(parentIds);
  grid->GetCellData()->AddArray(material);
  return grid;
}

vtkSmartPointer<vtkUnstructuredGrid> runFilter(
  vtkUnstructuredGrid* input, const FilterSettings& settings)
{
  vtkNew<vtkCoarseGrainedMeshAdaptation> filter;
  filter->SetInputData(input);
  filter->SetNumberOfPartitions(settings.numberOfPartitions);
  filter->SetNumberOfIterations(settings.numberOfIterations);
  filter->SetMethod(settings.method);
  filter->SetEdgeLengthFactor(settings.edgeLengthFactor);
  filter->SetVolumeFactor(settings.volumeFactor);
  filter->SetRadiusEdgeRatio(settings.radiusEdgeRatio);
  filter->SetNumberOfThreads(settings.numberOfThreads);
  filter->SetRegionArrayName(
    settings.regionArrayName.empty() ? nullptr : settings.regionArrayName.c_str());
  filter->SetColoringAlgorithm(settings.coloringAlgorithm);
  filter->SetPartitionByRegion(settings.partitionByRegion);
  filter->SetPartitionsPerRegion(settings.partitionsPerRegion);
  filter->SetImproveQuality(settings.improveQuality);
  filter->SetImproveInput(settings.improveInput);
  filter->SetNumberOfImprovementPasses(settings.improvementPasses);
  filter->Update();
  vtkSmartPointer<vtkUnstructuredGrid> output = filter->GetOutput();
  CGMESH_CHECK(output && output->GetNumberOfCells() > 0,
    "the filter produced no cells (partitions " << settings.numberOfPartitions << ", threads "
                                                << settings.numberOfThreads << ")");
  return output && output->GetNumberOfCells() > 0 ? output : nullptr;
}

void checkConformity(vtkUnstructuredGrid* input, vtkUnstructuredGrid* output)
{
  const cgmesh::MeshReport inputReport = inspectGrid(input, std::string());
  const cgmesh::MeshReport report = inspectGrid(output, std::string());
  CGMESH_CHECK(report.isValid(), report.describeProblems());
  CGMESH_CHECK(report.overSharedFaces == 0, report.overSharedFaces << " faces in 3+ tets");
  CGMESH_CHECK(report.misorientedFacePairs == 0, report.misorientedFacePairs << " misoriented");
  CGMESH_CHECK(report.invertedTets == 0, report.invertedTets << " inverted tets");
  CGMESH_CHECK(report.degenerateTets == 0, report.degenerateTets << " degenerate tets");
  CGMESH_CHECK(report.repeatedCornerTets == 0, report.repeatedCornerTets << " repeated corners");
  CGMESH_CHECK(report.duplicatePoints == 0, report.duplicatePoints << " duplicate points");
  CGMESH_CHECK(report.unusedPoints == 0, report.unusedPoints << " unused points");
  CGMESH_CHECK(relativelyEqual(report.volume, inputReport.volume, 1e-9),
    "volume " << report.volume << " != input volume " << inputReport.volume);
  CGMESH_CHECK(relativelyEqual(report.boundaryArea, inputReport.boundaryArea, 1e-9),
    "boundary area " << report.boundaryArea << " != input " << inputReport.boundaryArea);
}

void checkLinearField(vtkUnstructuredGrid* output)
{
  vtkDataArray* field = output->GetPointData()->GetArray("LinearField");
  CGMESH_CHECK(field, "point array LinearField missing");
  if (!field)
    return;
  vtkIdType wrongPoints = 0;
  for (vtkIdType pointId = 0; pointId < output->GetNumberOfPoints(); ++pointId)
  {
    const Vector point = pointOf(output, pointId);
    const double expected = point[0] + 2 * point[1] + 3 * point[2];
    wrongPoints += std::abs(field->GetComponent(pointId, 0) - expected) > 1e-12 ? 1 : 0;
  }
  CGMESH_CHECK(wrongPoints == 0, wrongPoints << " points with a wrong interpolated LinearField");
}

namespace
{

// Every child lies inside its parent, carries the parent's Material, and the children of a
// parent fill it exactly.
void checkChildrenOfParents(vtkUnstructuredGrid* input, vtkUnstructuredGrid* output)
{
  vtkDataArray* parentIds = output->GetCellData()->GetArray("ParentId");
  vtkDataArray* material = output->GetCellData()->GetArray("Material");
  vtkDataArray* inputMaterial = input->GetCellData()->GetArray("Material");
  CGMESH_CHECK(parentIds && material, "cell arrays ParentId/Material not copied");
  if (!parentIds || !material)
    return;
  std::vector<double> childVolumeSum(input->GetNumberOfCells(), 0.0);
  vtkIdType outsideChildren = 0;
  vtkIdType wrongMaterial = 0;
  for (vtkIdType cellId = 0; cellId < output->GetNumberOfCells(); ++cellId)
  {
    const auto parent = static_cast<vtkIdType>(parentIds->GetComponent(cellId, 0));
    const auto parentCorners = cellCorners(input, parent);
    const auto childCorners = cellCorners(output, cellId);
    for (const Vector& corner : childCorners)
      outsideChildren += minimumBarycentric(parentCorners, corner) < -1e-12 ? 1 : 0;
    childVolumeSum[parent] +=
      signedVolume(childCorners[0], childCorners[1], childCorners[2], childCorners[3]);
    wrongMaterial +=
      material->GetComponent(cellId, 0) != inputMaterial->GetComponent(parent, 0) ? 1 : 0;
  }
  vtkIdType unfilledParents = 0;
  for (vtkIdType parent = 0; parent < input->GetNumberOfCells(); ++parent)
  {
    const auto corners = cellCorners(input, parent);
    const double volume = signedVolume(corners[0], corners[1], corners[2], corners[3]);
    unfilledParents += relativelyEqual(childVolumeSum[parent], volume, 1e-9) ? 0 : 1;
  }
  CGMESH_CHECK(outsideChildren == 0, outsideChildren << " child corners outside their parent");
  CGMESH_CHECK(wrongMaterial == 0, wrongMaterial << " children with a wrong Material");
  CGMESH_CHECK(unfilledParents == 0, unfilledParents << " parents not filled by their children");
}

void checkArrayRange(vtkUnstructuredGrid* output, const char* name, double minimum, double maximum)
{
  vtkDataArray* array = output->GetCellData()->GetArray(name);
  CGMESH_CHECK(array && array->GetNumberOfTuples() == output->GetNumberOfCells(),
    "cell array " << name << " missing or of the wrong size");
  if (!array)
    return;
  double range[2];
  array->GetRange(range, 0);
  CGMESH_CHECK(range[0] >= minimum && range[1] <= maximum,
    name << " range [" << range[0] << ", " << range[1] << "] outside [" << minimum << ", "
         << maximum << "]");
}

std::vector<vtkIdType> fieldValues(vtkUnstructuredGrid* output, const char* name)
{
  std::vector<vtkIdType> values;
  auto* array = vtkLongArray::SafeDownCast(output->GetFieldData()->GetArray(name));
  CGMESH_CHECK(array, "field data " << name << " missing or not a vtkLongArray");
  for (vtkIdType tuple = 0; array && tuple < array->GetNumberOfTuples(); ++tuple)
    values.push_back(array->GetValue(tuple));
  return values;
}

// PartitionsPerColor and CellsPerColor count the distinct PartitionIds and the cells of each
// ColorId; ColorBalance is the largest PartitionsPerColor over the mean.
void checkColorPopulations(vtkUnstructuredGrid* output, int colors, int partitions)
{
  CGMESH_CHECK(vtkCoarseGrainedMeshAdaptation::ColoringAlgorithmToName(
                 static_cast<int>(fieldValue(output, "ColoringAlgorithmIndex"))) != nullptr,
    "field data ColoringAlgorithmIndex missing or not a colouring");
  // Text and possibly empty diagnostics stay out of the field data unless asked for.
  CGMESH_CHECK(!output->GetFieldData()->GetAbstractArray("ColoringAlgorithm") &&
      !output->GetFieldData()->GetAbstractArray("Method") &&
      !output->GetFieldData()->GetAbstractArray("FallbackPartitions"),
    "diagnostics in the field data without Diagnostics on");
  const std::vector<vtkIdType> partitionsPerColor = fieldValues(output, "PartitionsPerColor");
  const std::vector<vtkIdType> cellsPerColor = fieldValues(output, "CellsPerColor");
  vtkDataArray* colorIds = output->GetCellData()->GetArray("ColorId");
  vtkDataArray* partitionIds = output->GetCellData()->GetArray("PartitionId");
  if (partitionsPerColor.size() != static_cast<size_t>(colors) ||
    cellsPerColor.size() != static_cast<size_t>(colors) || !colorIds || !partitionIds)
  {
    CGMESH_CHECK(false, "colour populations do not hold one tuple per colour");
    return;
  }
  std::vector<vtkIdType> countedCells(colors, 0);
  std::vector<std::set<int>> partitionsOfColor(colors);
  for (vtkIdType cellId = 0; cellId < output->GetNumberOfCells(); ++cellId)
  {
    const int color = static_cast<int>(colorIds->GetComponent(cellId, 0));
    ++countedCells[color];
    partitionsOfColor[color].insert(static_cast<int>(partitionIds->GetComponent(cellId, 0)));
  }
  CGMESH_CHECK(countedCells == cellsPerColor, "CellsPerColor differs from the ColorId counts");
  for (int color = 0; color < colors; ++color)
  {
    CGMESH_CHECK(
      static_cast<vtkIdType>(partitionsOfColor[color].size()) <= partitionsPerColor[color],
      "colour " << color << " has cells of more partitions than PartitionsPerColor says");
  }
  CGMESH_CHECK(std::accumulate(
                 partitionsPerColor.begin(), partitionsPerColor.end(), vtkIdType(0)) == partitions,
    "PartitionsPerColor does not add up to NumberOfPartitions");
  const double largest =
    static_cast<double>(*std::max_element(partitionsPerColor.begin(), partitionsPerColor.end()));
  const double balance = fieldValue(output, "ColorBalance");
  CGMESH_CHECK(relativelyEqual(balance, largest * colors / partitions, 1e-12),
    "ColorBalance " << balance << " is not the largest colour over the mean");
}

} // namespace

void checkOutputArrays(vtkUnstructuredGrid* output)
{
  const double partitions = fieldValue(output, "NumberOfPartitions");
  const double colors = fieldValue(output, "NumberOfColors");
  CGMESH_CHECK(partitions >= 1 && colors >= 1, "partition/colour counts not positive");
  CGMESH_CHECK(fieldValue(output, "NumberOfThreads") >= 1, "thread count not positive");
  CGMESH_CHECK(fieldValue(output, "EdgeLengthThreshold") > 0, "threshold not positive");
  for (const char* phase : { "PartitionSeconds", "GraphSeconds", "ColorSeconds", "HealSeconds",
         "AdaptSeconds", "PostSeconds", "ImproveSeconds", "MergeSeconds", "InputSeconds",
         "OutputSeconds", "QualitySeconds", "TotalSeconds" })
  {
    CGMESH_CHECK(fieldValue(output, phase) >= 0, phase << " negative");
  }
  checkArrayRange(output, "PartitionId", 0, partitions - 1);
  checkArrayRange(output, "ColorId", 0, colors - 1);
  checkArrayRange(output, "EdgeRatio", 1.0, 1e6);
  checkArrayRange(output, "MinDihedralAngle", 1e-6, 180.0);
  checkArrayRange(output, "NearFormerInterface", 0, 1);
  checkColorPopulations(output, static_cast<int>(colors), static_cast<int>(partitions));
  const double method = fieldValue(output, "MethodIndex");
  CGMESH_CHECK(method == vtkCoarseGrainedMeshAdaptation::TEMPLATE ||
      method == vtkCoarseGrainedMeshAdaptation::DELAUNAY,
    "field data MethodIndex missing or not a method");
  for (const char* name : { "VolumeBound", "DelaunayFallbacks", "TetGenPoints", "EdgeRemovals",
         "FaceSwaps", "VertexMoves" })
  {
    CGMESH_CHECK(fieldValue(output, name) >= 0, name << " negative");
  }
}

double fieldValue(vtkUnstructuredGrid* output, const char* name)
{
  vtkDataArray* array = output->GetFieldData()->GetArray(name);
  CGMESH_CHECK(array && array->GetNumberOfTuples() == 1, "field data " << name << " missing");
  return array ? array->GetComponent(0, 0) : -1.0;
}

void checkDataTransfer(vtkUnstructuredGrid* input, vtkUnstructuredGrid* output)
{
  checkLinearField(output);
  checkChildrenOfParents(input, output);
  checkOutputArrays(output);
}

bool identicalGrids(
  vtkUnstructuredGrid* first, vtkUnstructuredGrid* second, std::string& difference)
{
  if (!sameBytes(first->GetPoints()->GetData(), second->GetPoints()->GetData()))
  {
    difference = "points differ";
    return false;
  }
  if (!sameBytes(first->GetCells()->GetOffsetsArray(), second->GetCells()->GetOffsetsArray()) ||
    !sameBytes(
      first->GetCells()->GetConnectivityArray(), second->GetCells()->GetConnectivityArray()) ||
    !sameBytes(first->GetCellTypesArray(), second->GetCellTypesArray()))
  {
    difference = "cells differ";
    return false;
  }
  return sameArrays(first->GetPointData(), second->GetPointData(), difference) &&
    sameArrays(first->GetCellData(), second->GetCellData(), difference);
}

} // namespace cgmesh_test
