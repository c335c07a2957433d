// Progress and phase timing of one filter run on the bundled FinFET with improvement on (both box
// sweeps run): the ProgressEvent values never decrease, start near 0 and end at 1; the phase
// seconds add up to the driver's wall time without gaps or double counting.
// Argument: Data/finfet-small.vtu.
#include "AdaptationDriver.h"
#include "FilterTestSupport.h"

#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <cstdlib>
#include <vector>

namespace
{

class ProgressRecorder : public vtkCommand
{
public:
  static ProgressRecorder* New() { return new ProgressRecorder; }
  void Execute(vtkObject*, unsigned long, void* callData) override
  {
    this->Values.push_back(*static_cast<double*>(callData));
  }
  std::vector<double> Values;
};

} // namespace

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::cerr << "usage: TestFilterProgress finfet-small.vtu\n";
    return 2;
  }
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(argv[1]);
  reader->Update();

  vtkNew<vtkCoarseGrainedMeshAdaptation> filter;
  filter->SetInputConnection(reader->GetOutputPort());
  filter->SetRegionArrayName("Material");
  filter->SetNumberOfPartitions(256);
  filter->SetEdgeLengthFactor(1.0); // splits some edges only: poor tets for both sweeps
  filter->SetNumberOfThreads(2);
  filter->ImproveQualityOn();
  vtkNew<ProgressRecorder> recorder;
  filter->AddObserver(vtkCommand::ProgressEvent, recorder);
  filter->Update();

  const cgmesh::AdaptationSummary* summary = filter->GetLastSummary();
  CGMESH_CHECK(summary != nullptr, "no summary");
  if (!summary)
  {
    return EXIT_FAILURE;
  }
  CGMESH_CHECK(summary->poorTets > 0, "no poor tets: the sweeps did not run");
  CGMESH_CHECK(summary->edgeRemovals + summary->faceSwaps + summary->vertexMoves > 0,
    "improvement changed nothing");

  const std::vector<double>& values = recorder->Values;
  CGMESH_CHECK(values.size() >= 20, "only " << values.size() << " progress values");
  CGMESH_CHECK(!values.empty() && values.front() <= 0.05, "first progress value too high");
  CGMESH_CHECK(!values.empty() && values.back() == 1.0, "progress does not end at 1");
  for (std::size_t i = 1; i < values.size(); ++i)
  {
    CGMESH_CHECK(values[i] >= values[i - 1],
      "progress went back from " << values[i - 1] << " to " << values[i] << " (value " << i << ")");
  }

  // Every phase got some time, and together they are the driver's run.
  double phases = 0;
  for (int phase = 0; phase < static_cast<int>(cgmesh::Phase::Count); ++phase)
  {
    const double seconds = summary->seconds[static_cast<cgmesh::Phase>(phase)];
    CGMESH_CHECK(seconds >= 0, cgmesh::phaseName(static_cast<cgmesh::Phase>(phase)) << " < 0");
    phases += seconds;
  }
  CGMESH_CHECK(summary->seconds[cgmesh::Phase::Improve] > 0, "no improvement time");
  CGMESH_CHECK(summary->seconds[cgmesh::Phase::Adapt] > 0, "no refinement time");
  // The filter's own steps account for the rest of its total: only bookkeeping is left over.
  const double filterTotal = filter->GetLastTotalSeconds();
  const double own = filter->GetLastInputSeconds() + filter->GetLastOutputSeconds() +
    filter->GetLastQualitySeconds();
  CGMESH_CHECK(filter->GetLastInputSeconds() > 0 && filter->GetLastOutputSeconds() > 0 &&
      filter->GetLastQualitySeconds() > 0,
    "input " << filter->GetLastInputSeconds() << " s, output " << filter->GetLastOutputSeconds()
             << " s, quality " << filter->GetLastQualitySeconds() << " s");
  const double leftOver = filterTotal - phases - own;
  CGMESH_CHECK(leftOver >= 0 && leftOver < 0.1 * filterTotal,
    "phases " << phases << " s and the filter's own " << own << " s of a total of " << filterTotal
              << " s");

  if (cgmesh_test::FailureCount > 0)
  {
    std::cerr << cgmesh_test::FailureCount << " checks failed\n";
    return EXIT_FAILURE;
  }
  std::cout << values.size() << " progress values, never decreasing:";
  for (double value : values)
  {
    std::cout << " " << value;
  }
  std::cout << "\nphases " << phases << " s of the filter's " << filterTotal << " s\n";
  return EXIT_SUCCESS;
}
