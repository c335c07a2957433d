// Attached data through vtkCoarseGrainedMeshAdaptation: cell arrays of every numeric type copied
// to the children exactly; point arrays of every type interpolated (integer ones when named in
// InterpolatedPointArrays, rounded) or kept as labels (integer ones by default).
#include "FilterRunChecks.h"

#include "cgmeshVTKConversion.h"

#include "ParallelFor.h"

#include "vtkBitArray.h"
#include "vtkCellData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkPointData.h"
#include "vtkStringArray.h"
#include "vtkVariant.h"

#include <array>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <map>
#include <string>

namespace
{

using namespace cgmesh_test;

const int NumericTypes[] = { VTK_CHAR, VTK_SIGNED_CHAR, VTK_UNSIGNED_CHAR, VTK_SHORT,
  VTK_UNSIGNED_SHORT, VTK_INT, VTK_UNSIGNED_INT, VTK_LONG, VTK_UNSIGNED_LONG, VTK_LONG_LONG,
  VTK_UNSIGNED_LONG_LONG, VTK_FLOAT, VTK_DOUBLE, VTK_ID_TYPE };

std::string arrayName(const char* kind, int type, int components)
{
  return std::string(kind) + "_" + typeName(type) + "_" + std::to_string(components);
}

// Component c of the point arrays: 10 (x + 2y + 3z) + c, whole numbers on the Kuhn cube of side
// 2 (coordinates are multiples of 1/2), between 0 and 62 (in range of every type).
double pointValue(const Vector& point, int component)
{
  return 10 * linearValue(point) + component;
}

// Component c of the cell arrays: a value between 0 and 99 that differs between neighbours.
double cellValue(vtkIdType cellId, int component)
{
  return static_cast<double>((7 * cellId + 13 * component) % 100);
}

vtkSmartPointer<vtkDataArray> makeArray(int type, int components, const std::string& name,
  vtkIdType tuples, const std::function<double(vtkIdType, int)>& value)
{
  vtkSmartPointer<vtkDataArray> array;
  array.TakeReference(vtkDataArray::CreateDataArray(type));
  array->SetName(name.c_str());
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  for (vtkIdType tuple = 0; tuple < tuples; ++tuple)
    for (int component = 0; component < components; ++component)
      array->SetComponent(tuple, component, value(tuple, component));
  return array;
}

void addArraysOfEveryType(vtkUnstructuredGrid* grid)
{
  for (const int type : NumericTypes)
  {
    for (const int components : { 1, 3 })
    {
      grid->GetPointData()->AddArray(
        makeArray(type, components, arrayName("Point", type, components), grid->GetNumberOfPoints(),
          [grid](vtkIdType pointId, int component)
          { return pointValue(pointOf(grid, pointId), component); }));
      grid->GetCellData()->AddArray(makeArray(type, components, arrayName("Cell", type, components),
        grid->GetNumberOfCells(), cellValue));
    }
  }
  vtkNew<vtkStringArray> names;
  names->SetName("CellName");
  for (vtkIdType cellId = 0; cellId < grid->GetNumberOfCells(); ++cellId)
    names->InsertNextValue("cell " + std::to_string(cellId));
  grid->GetCellData()->AddArray(names);
}

// Every child carries its parent's (ParentId) values exactly.
void checkCellArraysCopied(vtkUnstructuredGrid* input, vtkUnstructuredGrid* output)
{
  vtkDataArray* parentIds = output->GetCellData()->GetArray("ParentId");
  for (int index = 0; parentIds && index < input->GetCellData()->GetNumberOfArrays(); ++index)
  {
    vtkAbstractArray* source = input->GetCellData()->GetAbstractArray(index);
    vtkAbstractArray* copied = output->GetCellData()->GetAbstractArray(source->GetName());
    CGMESH_CHECK(copied && copied->GetDataType() == source->GetDataType() &&
        copied->GetNumberOfComponents() == source->GetNumberOfComponents() &&
        copied->GetNumberOfTuples() == output->GetNumberOfCells(),
      "cell array " << source->GetName() << " missing or of another type or size");
    if (!copied || copied->GetDataType() != source->GetDataType())
      continue;
    const int components = source->GetNumberOfComponents();
    vtkIdType wrongValues = 0;
    for (vtkIdType cellId = 0; cellId < output->GetNumberOfCells(); ++cellId)
    {
      const auto parent = static_cast<vtkIdType>(parentIds->GetComponent(cellId, 0));
      for (int component = 0; component < components; ++component)
      {
        const bool same = copied->GetVariantValue(cellId * components + component) ==
          source->GetVariantValue(parent * components + component);
        wrongValues += same ? 0 : 1;
      }
    }
    CGMESH_CHECK(wrongValues == 0,
      "cell array " << source->GetName() << ": " << wrongValues << " values not copied exactly");
  }
}

// Interpolated values of a point array against 10 (x + 2y + 3z) + c: floating-point types to
// rounding error, integer types rounded to within 1.
void checkPointArray(vtkUnstructuredGrid* output, int type, int components)
{
  const std::string name = arrayName("Point", type, components);
  vtkDataArray* array = output->GetPointData()->GetArray(name.c_str());
  CGMESH_CHECK(array && array->GetDataType() == type &&
      array->GetNumberOfComponents() == components &&
      array->GetNumberOfTuples() == output->GetNumberOfPoints(),
    "point array " << name << " missing or of another type or size");
  if (!array || array->GetDataType() != type)
    return;
  const bool integral = type != VTK_FLOAT && type != VTK_DOUBLE;
  const double tolerance = type == VTK_DOUBLE ? 1e-12 : type == VTK_FLOAT ? 1e-5 : 1.0;
  vtkIdType wrongValues = 0;
  vtkIdType fractionalValues = 0;
  for (vtkIdType pointId = 0; pointId < output->GetNumberOfPoints(); ++pointId)
  {
    const Vector point = pointOf(output, pointId);
    for (int component = 0; component < components; ++component)
    {
      const double value = array->GetComponent(pointId, component);
      wrongValues += std::abs(value - pointValue(point, component)) <= tolerance ? 0 : 1;
      fractionalValues += integral && value != std::round(value) ? 1 : 0;
    }
  }
  CGMESH_CHECK(wrongValues == 0,
    "point array " << name << ": " << wrongValues << " values off the linear field");
  CGMESH_CHECK(fractionalValues == 0, "point array " << name << ": fractional values");
}

// An integer point array left a labelling: a point where an input point was keeps its value;
// a new one, between points whose values all differ on this field, gets 0.
void checkPointLabels(
  vtkUnstructuredGrid* input, vtkUnstructuredGrid* output, int type, int components)
{
  const std::string name = arrayName("Point", type, components);
  vtkDataArray* before = input->GetPointData()->GetArray(name.c_str());
  vtkDataArray* after = output->GetPointData()->GetArray(name.c_str());
  CGMESH_CHECK(
    after && after->GetDataType() == type && after->GetNumberOfComponents() == components,
    "point array " << name << " missing or of another type");
  if (!after || !before)
    return;
  std::map<std::array<double, 3>, vtkIdType> inputPointAt;
  for (vtkIdType pointId = 0; pointId < input->GetNumberOfPoints(); ++pointId)
  {
    const Vector point = pointOf(input, pointId);
    inputPointAt[{ point[0], point[1], point[2] }] = pointId;
  }
  vtkIdType wrongValues = 0, newPoints = 0;
  for (vtkIdType pointId = 0; pointId < output->GetNumberOfPoints(); ++pointId)
  {
    const Vector point = pointOf(output, pointId);
    const auto found = inputPointAt.find({ point[0], point[1], point[2] });
    newPoints += found == inputPointAt.end() ? 1 : 0;
    for (int component = 0; component < components; ++component)
    {
      const double expected =
        found == inputPointAt.end() ? 0.0 : before->GetComponent(found->second, component);
      wrongValues += after->GetComponent(pointId, component) == expected ? 0 : 1;
    }
  }
  CGMESH_CHECK(newPoints > 0, "point array " << name << ": no new point to check");
  CGMESH_CHECK(wrongValues == 0,
    "point array " << name << ": " << wrongValues << " values not kept as labels");
}

void test_attachedData()
{
  vtkSmartPointer<vtkUnstructuredGrid> input = cgmesh_test::makeCubeWithTestArrays(2);
  addArraysOfEveryType(input);
  // Integer point arrays are labels unless named for interpolation: both ways are checked.
  std::string integerPointArrays;
  for (const int type : NumericTypes)
    for (const int components : { 1, 3 })
      if (type != VTK_FLOAT && type != VTK_DOUBLE)
        integerPointArrays +=
          (integerPointArrays.empty() ? "" : ",") + arrayName("Point", type, components);
  for (const bool interpolated : { true, false })
  {
    FilterRun run(input, interpolated ? "arrays of every type" : "integer point labels");
    run.Filter->SetNumberOfIterations(2);
    run.Filter->SetEdgeLengthFactor(0.25);
    run.Filter->SetInterpolatedPointArrays(interpolated ? integerPointArrays.c_str() : "");
    expectRefinement(run, 1.0);
    vtkUnstructuredGrid* output = run.output();
    if (output->GetNumberOfCells() == 0)
      return;
    CGMESH_CHECK(output->GetNumberOfPoints() > 2 * input->GetNumberOfPoints(), "few new points");
    cgmesh_test::checkDataTransfer(input, output);
    checkCellArraysCopied(input, output);
    for (const int type : NumericTypes)
      for (const int components : { 1, 3 })
        if (interpolated || type == VTK_FLOAT || type == VTK_DOUBLE)
          checkPointArray(output, type, components);
        else
          checkPointLabels(input, output, type, components);
  }
}

} // namespace

// Every array of `actual` holds what the same array of `expected` holds: name, attribute role,
// type, shape and every value.
void checkSameCellData(vtkCellData* expected, vtkCellData* actual, const std::string& what)
{
  CGMESH_CHECK(actual->GetNumberOfArrays() == expected->GetNumberOfArrays(),
    what << ": " << actual->GetNumberOfArrays() << " arrays instead of "
         << expected->GetNumberOfArrays());
  for (int index = 0; index < std::min(actual->GetNumberOfArrays(), expected->GetNumberOfArrays());
       ++index)
  {
    vtkAbstractArray* want = expected->GetAbstractArray(index);
    vtkAbstractArray* got = actual->GetAbstractArray(index);
    const std::string name = want->GetName() ? want->GetName() : "(unnamed)";
    CGMESH_CHECK(got->GetDataType() == want->GetDataType() &&
        got->GetNumberOfComponents() == want->GetNumberOfComponents() &&
        got->GetNumberOfValues() == want->GetNumberOfValues() &&
        actual->IsArrayAnAttribute(index) == expected->IsArrayAnAttribute(index) &&
        (got->GetName() ? std::string(got->GetName()) : "(unnamed)") == name,
      what << ": array " << index << " (" << name << ") differs in kind");
    vtkIdType wrongValues = 0;
    for (vtkIdType value = 0; value < std::min(got->GetNumberOfValues(), want->GetNumberOfValues());
         ++value)
    {
      wrongValues += got->GetVariantValue(value) == want->GetVariantValue(value) ? 0 : 1;
    }
    CGMESH_CHECK(wrongValues == 0, what << ": array " << name << ", " << wrongValues << " values");
  }
}

// copyCellData on two threads gives what VTK's CopyData gives: plain arrays of every type copied
// as bytes in ranges, string and bit arrays tuple by tuple, attributes included, and with an
// unnamed array, which cannot be paired with its source, VTK's own copy.
void test_copyCellDataMatchesVTK()
{
  constexpr vtkIdType InputCells = 5000;
  constexpr vtkIdType OutputCells = 200000; // several ranges of IndicesPerCopyRange
  const auto sourceOf = [](vtkIdType cellId)
  {
    return (cellId * 7919) % InputCells;
  };
  for (const bool unnamedArray : { false, true })
  {
    vtkNew<vtkCellData> input;
    for (const int type : NumericTypes)
    {
      input->AddArray(makeArray(type, 3, arrayName("Cell", type, 3), InputCells, cellValue));
    }
    input->SetScalars(makeArray(VTK_FLOAT, 1, "Scalars", InputCells, cellValue));
    vtkNew<vtkStringArray> names;
    names->SetName("CellName");
    vtkNew<vtkBitArray> bits;
    bits->SetName("CellBit");
    for (vtkIdType cellId = 0; cellId < InputCells; ++cellId)
    {
      names->InsertNextValue("cell " + std::to_string(cellId));
      bits->InsertNextValue(static_cast<int>(cellId % 3 == 0));
    }
    input->AddArray(names);
    input->AddArray(bits);
    if (unnamedArray)
    {
      vtkSmartPointer<vtkDataArray> unnamed = makeArray(VTK_INT, 1, "", InputCells, cellValue);
      unnamed->SetName(nullptr);
      input->AddArray(unnamed);
    }

    vtkNew<vtkCellData> expected;
    expected->CopyAllocate(input, OutputCells);
    vtkNew<vtkIdList> sourceIds;
    vtkNew<vtkIdList> targetIds;
    for (vtkIdType cellId = 0; cellId < OutputCells; ++cellId)
    {
      sourceIds->InsertNextId(sourceOf(cellId));
      targetIds->InsertNextId(cellId);
    }
    expected->CopyData(input, sourceIds, targetIds);

    vtkNew<vtkCellData> actual;
    cgmesh::copyCellData(input, OutputCells, sourceOf, actual, cgmesh::parallelForOn(2));
    checkSameCellData(expected, actual,
      unnamedArray ? "copyCellData, an unnamed array" : "copyCellData, every kind of array");
  }
}

int main()
{
  test_copyCellDataMatchesVTK();
  test_attachedData();
  if (cgmesh_test::FailureCount > 0)
  {
    std::cerr << cgmesh_test::FailureCount << " checks failed\n";
    return EXIT_FAILURE;
  }
  std::cout << "all attached-data checks passed\n";
  return EXIT_SUCCESS;
}
