#include "cgmeshPointData.h"

#include "cgmeshVTKConversion.h"

#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>

namespace cgmesh
{
namespace
{

// The provenance-weighted sum of the input's point data (VTK's interpolation; it rounds integer
// types and skips vtkIdTypeArrays).
void interpolatePointData(
  vtkPointData* inputPointData, const PointProvenance& provenance, vtkPointData* outputPointData)
{
  const vtkIdType numberOfPoints = static_cast<vtkIdType>(provenance.offsets.size()) - 1;
  outputPointData->InterpolateAllocate(inputPointData, numberOfPoints);
  vtkNew<vtkIdList> sourceIds;
  std::vector<double> weights;
  for (vtkIdType pointId = 0; pointId < numberOfPoints; ++pointId)
  {
    const auto begin = provenance.offsets[pointId];
    const auto end = provenance.offsets[pointId + 1];
    sourceIds->SetNumberOfIds(static_cast<vtkIdType>(end - begin));
    weights.resize(static_cast<size_t>(end - begin));
    for (auto source = begin; source < end; ++source)
    {
      sourceIds->SetId(static_cast<vtkIdType>(source - begin), provenance.sources[source]);
      weights[source - begin] = provenance.weights[source];
    }
    outputPointData->InterpolatePoint(inputPointData, pointId, sourceIds, weights.data());
  }
}

// vtkDataSetAttributes never interpolates vtkIdTypeArrays; plain ones (not global or pedigree
// ids, which have no values between points) are interpolated here like other integer arrays:
// the provenance-weighted sum, rounded to the nearest integer.
void interpolateIdTypeArrays(
  vtkPointData* inputPointData, const PointProvenance& provenance, vtkPointData* outputPointData)
{
  const vtkIdType numberOfPoints = static_cast<vtkIdType>(provenance.offsets.size()) - 1;
  for (int index = 0; index < inputPointData->GetNumberOfArrays(); ++index)
  {
    auto* source = vtkIdTypeArray::SafeDownCast(inputPointData->GetAbstractArray(index));
    const int attribute = inputPointData->IsArrayAnAttribute(index);
    if (!source || !source->GetName() || outputPointData->GetAbstractArray(source->GetName()) ||
      attribute == vtkDataSetAttributes::GLOBALIDS ||
      attribute == vtkDataSetAttributes::PEDIGREEIDS)
    {
      continue;
    }
    const int components = source->GetNumberOfComponents();
    vtkNew<vtkIdTypeArray> interpolated;
    interpolated->SetName(source->GetName());
    interpolated->SetNumberOfComponents(components);
    interpolated->SetNumberOfTuples(numberOfPoints);
    for (vtkIdType pointId = 0; pointId < numberOfPoints; ++pointId)
    {
      for (int component = 0; component < components; ++component)
      {
        double value = 0;
        for (auto entry = provenance.offsets[pointId]; entry < provenance.offsets[pointId + 1];
             ++entry)
        {
          value += provenance.weights[entry] *
            static_cast<double>(source->GetTypedComponent(provenance.sources[entry], component));
        }
        interpolated->SetTypedComponent(pointId, component, std::llround(value));
      }
    }
    outputPointData->AddArray(interpolated);
  }
}

// Rewrites `labels` (already sized): each point's value is the one its sources share, else 0.
void keepSharedLabels(vtkDataArray* source, const PointProvenance& provenance, vtkDataArray* labels)
{
  const vtkIdType numberOfPoints = static_cast<vtkIdType>(provenance.offsets.size()) - 1;
  const int components = source->GetNumberOfComponents();
  for (vtkIdType point = 0; point < numberOfPoints; ++point)
  {
    for (int component = 0; component < components; ++component)
    {
      bool first = true, agreed = true;
      double shared = 0;
      for (auto entry = provenance.offsets[point]; entry < provenance.offsets[point + 1]; ++entry)
      {
        if (!(provenance.weights[entry] > 1e-12))
        {
          continue; // a source in name only: the point lies on the face opposite it
        }
        const double value = source->GetComponent(provenance.sources[entry], component);
        agreed = agreed && (first || value == shared);
        shared = value;
        first = false;
      }
      labels->SetComponent(point, component, agreed && !first ? shared : 0.0);
    }
  }
}

// Global point ids stay with the input points that survive; new points get ids above the input's
// largest, in output order, so the ids stay unique and do not depend on the thread count.
void extendGlobalIds(vtkPointData* input, const PointProvenance& provenance, vtkPointData* output)
{
  vtkDataArray* ids = input->GetGlobalIds();
  const vtkIdType numberOfPoints = static_cast<vtkIdType>(provenance.offsets.size()) - 1;
  if (!ids || ids->GetNumberOfComponents() != 1 ||
    static_cast<vtkIdType>(provenance.inputPoints.size()) != numberOfPoints)
  {
    return;
  }
  vtkSmartPointer<vtkDataArray> extended = vtk::TakeSmartPointer(ids->NewInstance());
  extended->SetName(ids->GetName());
  extended->SetNumberOfTuples(numberOfPoints);
  double next = ids->GetNumberOfTuples() > 0 ? ids->GetRange(0)[1] + 1 : 0;
  for (vtkIdType point = 0; point < numberOfPoints; ++point)
  {
    const PointId inputPoint = provenance.inputPoints[point];
    extended->SetComponent(point, 0, inputPoint >= 0 ? ids->GetComponent(inputPoint, 0) : next++);
  }
  output->SetGlobalIds(extended);
}

} // namespace

void transferPointData(vtkPointData* input, const PointProvenance& provenance,
  const std::vector<std::string>& interpolatedArrays, vtkPointData* output)
{
  interpolatePointData(input, provenance, output);
  interpolateIdTypeArrays(input, provenance, output);
  extendGlobalIds(input, provenance, output);
  for (int index = 0; index < input->GetNumberOfArrays(); ++index)
  {
    vtkDataArray* source = input->GetArray(index);
    if (!source || !source->GetName() || !isIntegerDataType(source->GetDataType()) ||
      source == input->GetGlobalIds() ||
      std::find(interpolatedArrays.begin(), interpolatedArrays.end(), source->GetName()) !=
        interpolatedArrays.end())
    {
      continue;
    }
    if (vtkDataArray* labels = output->GetArray(source->GetName()))
    {
      keepSharedLabels(source, provenance, labels);
    }
  }
}

} // namespace cgmesh
