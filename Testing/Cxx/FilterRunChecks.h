// A harness for filter tests that run vtkCoarseGrainedMeshAdaptation on a hand-made input: one
// run with its messages observed and the input checked unchanged afterwards, the expectations of
// an error or of a valid refinement, and small helpers on points and array types.
#ifndef cgmesh_FilterRunChecks_h
#define cgmesh_FilterRunChecks_h

#include "FilterTestSupport.h"

#include "vtkCoarseGrainedMeshAdaptation.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <array>
#include <cmath>
#include <initializer_list>
#include <string>
#include <utility>

namespace cgmesh_test
{

using Vector = std::array<double, 3>;

// Counts errors and warnings and keeps their text (and keeps VTK from printing them).
class MessageObserver : public vtkCommand
{
public:
  static MessageObserver* New() { return new MessageObserver; }
  void Execute(vtkObject*, unsigned long eventId, void* callData) override
  {
    (eventId == vtkCommand::ErrorEvent ? this->Errors : this->Warnings)++;
    this->Text += callData ? static_cast<const char*>(callData) : "";
    this->Text += "\n";
  }
  int Errors = 0;
  int Warnings = 0;
  std::string Text;
};

// A deep copy and the MTime of the input, taken before the filter runs.
struct InputSnapshot
{
  vtkNew<vtkUnstructuredGrid> Copy;
  vtkMTimeType Time = 0;

  explicit InputSnapshot(vtkUnstructuredGrid* input)
  {
    this->Copy->DeepCopy(input);
    this->Time = input->GetMTime();
  }
};

inline void checkInputUnchanged(
  vtkUnstructuredGrid* input, const InputSnapshot& snapshot, const std::string& caseName)
{
  CGMESH_CHECK(input->GetMTime() == snapshot.Time, caseName << ": the input's MTime changed");
  CGMESH_CHECK(input->GetNumberOfPoints() == snapshot.Copy->GetNumberOfPoints() &&
      input->GetNumberOfCells() == snapshot.Copy->GetNumberOfCells(),
    caseName << ": the input's point or cell count changed");
  CGMESH_CHECK(input->GetFieldData()->GetNumberOfArrays() ==
      snapshot.Copy->GetFieldData()->GetNumberOfArrays(),
    caseName << ": the input's field data changed");
  if (input->GetNumberOfPoints() == 0 || input->GetNumberOfCells() == 0)
  {
    return; // identicalGrids needs points and cells
  }
  std::string difference;
  CGMESH_CHECK(cgmesh_test::identicalGrids(input, snapshot.Copy, difference),
    caseName << ": the input was modified: " << difference);
}

// One filter run on `input` (4 partitions, 1 iteration, factor 0.5, 2 threads unless changed),
// with its messages observed and a snapshot of the input.
struct FilterRun
{
  vtkUnstructuredGrid* Input;
  std::string CaseName;
  InputSnapshot Snapshot;
  vtkNew<vtkCoarseGrainedMeshAdaptation> Filter;
  vtkNew<MessageObserver> Messages;
  int UpdateResult = -1;

  FilterRun(vtkUnstructuredGrid* input, std::string caseName)
    : Input(input)
    , CaseName(std::move(caseName))
    , Snapshot(input)
  {
    this->Filter->SetInputData(input);
    this->Filter->SetNumberOfPartitions(4);
    this->Filter->SetNumberOfIterations(1);
    this->Filter->SetEdgeLengthFactor(0.5);
    this->Filter->SetNumberOfThreads(2);
    for (vtkObject* object : { static_cast<vtkObject*>(this->Filter.Get()),
           static_cast<vtkObject*>(this->Filter->GetExecutive()) })
    {
      object->AddObserver(vtkCommand::ErrorEvent, this->Messages);
      object->AddObserver(vtkCommand::WarningEvent, this->Messages);
    }
  }

  vtkUnstructuredGrid* output() { return this->Filter->GetOutput(); }
  bool said(const std::string& text) const
  {
    return this->Messages->Text.find(text) != std::string::npos;
  }

  void update()
  {
    this->UpdateResult = this->Filter->GetExecutive()->Update();
    checkInputUnchanged(this->Input, this->Snapshot, this->CaseName);
  }
};

// RequestData fails with an error whose text holds every phrase, and the output is empty.
inline void expectError(FilterRun& run, std::initializer_list<const char*> phrases)
{
  run.update();
  const std::string& name = run.CaseName;
  CGMESH_CHECK(run.UpdateResult == 0, name << ": Update succeeded");
  CGMESH_CHECK(run.Messages->Errors > 0, name << ": no error reported");
  for (const char* phrase : phrases)
  {
    CGMESH_CHECK(run.said(phrase),
      name << ": the error does not say '" << phrase << "': " << run.Messages->Text);
  }
  CGMESH_CHECK(run.output()->GetNumberOfCells() == 0 && run.output()->GetNumberOfPoints() == 0,
    name << ": the output is not empty after an error");
}

// The output is a valid, conforming, positively oriented mesh of `expectedVolume` (1e-9 relative)
// without duplicate or unused points.
inline void checkValidMesh(
  vtkUnstructuredGrid* output, double expectedVolume, const std::string& name)
{
  const cgmesh::MeshReport report = cgmesh_test::inspectGrid(output, std::string());
  CGMESH_CHECK(report.isValid(), name << ": " << report.describeProblems());
  CGMESH_CHECK(report.invertedTets == 0 && report.misorientedFacePairs == 0,
    name << ": " << report.invertedTets << " inverted tets, " << report.misorientedFacePairs
         << " misoriented face pairs");
  CGMESH_CHECK(report.degenerateTets == 0, name << ": " << report.degenerateTets << " degenerate");
  CGMESH_CHECK(report.duplicatePoints == 0 && report.unusedPoints == 0,
    name << ": " << report.duplicatePoints << " duplicate, " << report.unusedPoints << " unused");
  CGMESH_CHECK(std::abs(report.volume - expectedVolume) <= 1e-9 * std::abs(expectedVolume),
    name << ": volume " << report.volume << ", expected " << expectedVolume);
}

// The run succeeds without errors and refines the input into a valid mesh of `expectedVolume`.
inline void expectRefinement(FilterRun& run, double expectedVolume)
{
  run.update();
  const std::string& name = run.CaseName;
  CGMESH_CHECK(run.UpdateResult == 1 && run.Messages->Errors == 0,
    name << ": the run failed: " << run.Messages->Text);
  vtkUnstructuredGrid* output = run.output();
  CGMESH_CHECK(output->GetNumberOfCells() > run.Input->GetNumberOfCells(),
    name << ": " << run.Input->GetNumberOfCells() << " -> " << output->GetNumberOfCells()
         << " cells, not refined");
  if (output->GetNumberOfCells() > 0)
  {
    checkValidMesh(output, expectedVolume, name);
  }
}

inline std::string typeName(int type)
{
  vtkSmartPointer<vtkDataArray> array;
  array.TakeReference(vtkDataArray::CreateDataArray(type));
  return array->GetDataTypeAsString();
}

inline Vector pointOf(vtkUnstructuredGrid* grid, vtkIdType pointId)
{
  Vector point;
  grid->GetPoint(pointId, point.data());
  return point;
}

inline double linearValue(const Vector& point)
{
  return point[0] + 2 * point[1] + 3 * point[2];
}

} // namespace cgmesh_test

#endif
