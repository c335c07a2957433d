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
#include <sstream>

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
        if (!(provenance.weights[entry] > NegligibleSourceWeight))
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
  const std::vector<std::string>& interpolatedArrays, const std::vector<std::string>& labelArrays,
  vtkPointData* output)
{
  const auto named = [](const std::vector<std::string>& names, const char* name)
  {
    return std::find(names.begin(), names.end(), name) != names.end();
  };
  interpolatePointData(input, provenance, output);
  interpolateIdTypeArrays(input, provenance, output);
  extendGlobalIds(input, provenance, output);
  for (int index = 0; index < input->GetNumberOfArrays(); ++index)
  {
    vtkDataArray* source = input->GetArray(index);
    if (!source || !source->GetName() || source == input->GetGlobalIds())
    {
      continue;
    }
    const bool label = isIntegerDataType(source->GetDataType())
      ? !named(interpolatedArrays, source->GetName())
      : named(labelArrays, source->GetName());
    if (!label)
    {
      continue;
    }
    if (vtkDataArray* labels = output->GetArray(source->GetName()))
    {
      keepSharedLabels(source, provenance, labels);
    }
  }
}

Status checkPointArrayRoles(vtkPointData* input, const std::vector<std::string>& interpolatedArrays,
  const std::vector<std::string>& labelArrays)
{
  const auto missing = [input](const std::string& name, const char* property)
  {
    std::string known;
    for (int index = 0; index < input->GetNumberOfArrays(); ++index)
    {
      const char* arrayName = input->GetArrayName(index);
      if (arrayName && input->GetArray(index))
        known += (known.empty() ? "'" : ", '") + std::string(arrayName) + "'";
    }
    return Status::failure(std::string(property) + " names '" + name +
      "', which is no numeric point array of the input (its numeric point arrays: " +
      (known.empty() ? std::string("none") : known) + ")");
  };
  for (const std::string& name : interpolatedArrays)
  {
    if (!input->GetArray(name.c_str()))
      return missing(name, "InterpolatedPointArrays");
  }
  for (const std::string& name : labelArrays)
  {
    vtkDataArray* array = input->GetArray(name.c_str());
    if (!array)
      return missing(name, "LabelPointArrays");
    if (std::find(interpolatedArrays.begin(), interpolatedArrays.end(), name) !=
      interpolatedArrays.end())
      return Status::failure("point array '" + name +
        "' is named both in InterpolatedPointArrays and in LabelPointArrays");
    for (vtkIdType point = 0; point < array->GetNumberOfTuples(); ++point)
    {
      for (int component = 0; component < array->GetNumberOfComponents(); ++component)
      {
        const double value = array->GetComponent(point, component);
        if (!std::isfinite(value))
        {
          std::ostringstream message;
          message << "point array '" << name << "' (LabelPointArrays) holds " << value
                  << " at point " << point << "; labels must be finite numbers";
          return Status::failure(message.str());
        }
      }
    }
  }
  return Status::success();
}

std::vector<std::string> splitNames(const std::string& text)
{
  std::vector<std::string> names;
  std::size_t start = 0;
  while (start <= text.size())
  {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    std::string name = text.substr(start, comma - start);
    name.erase(0, name.find_first_not_of(" \t"));
    name.erase(name.find_last_not_of(" \t") + 1);
    if (!name.empty())
    {
      names.push_back(name);
    }
    start = comma + 1;
  }
  return names;
}

} // namespace cgmesh
