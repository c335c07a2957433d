// A plain VTK pipeline: XML reader -> vtkCoarseGrainedMeshAdaptation -> XML and legacy writers,
// then both files are read back and compared with the filter output.
//   TestVTKPipeline SCRATCH_DIRECTORY
#include "FilterTestSupport.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCoarseGrainedMeshAdaptation.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridReader.h"
#include "vtkUnstructuredGridWriter.h"
#include "vtkXMLUnstructuredGridReader.h"
#include "vtkXMLUnstructuredGridWriter.h"

#include <cstdlib>
#include <string>

namespace
{

// Value-wise comparison: file formats may change an array's storage type, never its values.
bool equalValues(vtkDataArray* first, vtkDataArray* second)
{
  if (!first || !second || first->GetNumberOfValues() != second->GetNumberOfValues())
    return false;
  const int components = first->GetNumberOfComponents();
  for (vtkIdType value = 0; value < first->GetNumberOfValues(); ++value)
  {
    if (first->GetComponent(value / components, value % components) !=
      second->GetComponent(value / components, value % components))
      return false;
  }
  return true;
}

void checkSameGrid(vtkUnstructuredGrid* expected, vtkUnstructuredGrid* actual, const char* what)
{
  CGMESH_CHECK(expected->GetNumberOfCells() == actual->GetNumberOfCells(), what << ": cell count");
  CGMESH_CHECK(equalValues(expected->GetPoints()->GetData(), actual->GetPoints()->GetData()),
    what << ": points differ");
  CGMESH_CHECK(equalValues(expected->GetCells()->GetConnectivityArray(),
                 actual->GetCells()->GetConnectivityArray()),
    what << ": connectivity differs");
  for (vtkFieldData* data : { static_cast<vtkFieldData*>(expected->GetPointData()),
         static_cast<vtkFieldData*>(expected->GetCellData()) })
  {
    vtkFieldData* actualData = data == expected->GetPointData()
      ? static_cast<vtkFieldData*>(actual->GetPointData())
      : static_cast<vtkFieldData*>(actual->GetCellData());
    for (int index = 0; index < data->GetNumberOfArrays(); ++index)
    {
      const char* name = data->GetArrayName(index);
      CGMESH_CHECK(equalValues(data->GetArray(index), actualData->GetArray(name)),
        what << ": array " << name << " differs");
    }
  }
}

void test_xmlAndLegacyRoundTrip(const std::string& directory)
{
  const std::string inputFile = directory + "/pipeline-input.vtu";
  vtkNew<vtkXMLUnstructuredGridWriter> inputWriter;
  inputWriter->SetInputData(cgmesh_test::makeCubeWithTestArrays(4));
  inputWriter->SetFileName(inputFile.c_str());
  CGMESH_CHECK(inputWriter->Write() == 1, "cannot write " << inputFile);

  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(inputFile.c_str());
  vtkNew<vtkCoarseGrainedMeshAdaptation> filter;
  filter->SetInputConnection(reader->GetOutputPort());
  filter->SetNumberOfPartitions(8);
  filter->SetNumberOfIterations(2);
  filter->SetEdgeLengthFactor(0.25);
  filter->SetRegionArrayName("Material");

  const std::string xmlFile = directory + "/pipeline-output.vtu";
  vtkNew<vtkXMLUnstructuredGridWriter> xmlWriter;
  xmlWriter->SetInputConnection(filter->GetOutputPort());
  xmlWriter->SetFileName(xmlFile.c_str());
  CGMESH_CHECK(xmlWriter->Write() == 1, "cannot write " << xmlFile);
  const std::string legacyFile = directory + "/pipeline-output.vtk";
  vtkNew<vtkUnstructuredGridWriter> legacyWriter;
  legacyWriter->SetInputConnection(filter->GetOutputPort());
  legacyWriter->SetFileName(legacyFile.c_str());
  legacyWriter->SetFileTypeToBinary();
  CGMESH_CHECK(legacyWriter->Write() == 1, "cannot write " << legacyFile);

  vtkUnstructuredGrid* output = filter->GetOutput();
  CGMESH_CHECK(output->GetNumberOfCells() == 64 * 6 * 4 * 4 * 4, "unexpected cell count");
  cgmesh_test::checkConformity(reader->GetOutput(), output);
  cgmesh_test::checkDataTransfer(reader->GetOutput(), output);

  vtkNew<vtkXMLUnstructuredGridReader> xmlReader;
  xmlReader->SetFileName(xmlFile.c_str());
  xmlReader->Update();
  checkSameGrid(output, xmlReader->GetOutput(), "XML round trip");
  vtkNew<vtkUnstructuredGridReader> legacyReader;
  legacyReader->SetFileName(legacyFile.c_str());
  legacyReader->ReadAllScalarsOn();
  legacyReader->ReadAllFieldsOn();
  legacyReader->Update();
  checkSameGrid(output, legacyReader->GetOutput(), "legacy round trip");
}

} // namespace

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::cerr << "usage: TestVTKPipeline SCRATCH_DIRECTORY\n";
    return EXIT_FAILURE;
  }
  test_xmlAndLegacyRoundTrip(argv[1]);
  if (cgmesh_test::FailureCount > 0)
  {
    std::cerr << cgmesh_test::FailureCount << " checks failed\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
