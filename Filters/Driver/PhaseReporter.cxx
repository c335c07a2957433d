#include "PhaseReporter.h"

#include <algorithm>

namespace cgmesh
{
namespace
{

// Shares of the progress bar, from measured runs (template and Delaunay, FinFET and cube):
// refinement and the sweeps dominate, partitioning is next. A run that does not improve its input
// skips that share.
constexpr std::array<double, static_cast<int>(Stage::Count)> StageShare = { 0.02, 0.10, 0.08, 0.52,
  0.24, 0.04 };
constexpr std::array<const char*, static_cast<int>(Stage::Count)> StageName = { "preparing",
  "partitioning", "improving the input", "refining", "improving", "merging" };
constexpr std::array<const char*, static_cast<int>(Phase::Count)> PhaseName = { "prepare",
  "partition", "graph", "color", "heal", "adapt", "improve", "post", "merge" };

} // namespace

double PhaseSeconds::total() const
{
  double sum = 0;
  for (double value : this->seconds)
  {
    sum += value;
  }
  return sum;
}

const char* phaseName(Phase phase)
{
  return PhaseName[static_cast<int>(phase)];
}

void PhaseReporter::enter(Phase phase)
{
  const double elapsed = this->Clock.lap();
  if (this->Running != Phase::Count)
  {
    this->Seconds[this->Running] += elapsed;
  }
  this->Running = phase;
}

void PhaseReporter::stop()
{
  this->enter(Phase::Count);
}

void PhaseReporter::progress(Stage stage, double fraction)
{
  double start = 0;
  for (int s = 0; s < static_cast<int>(stage); ++s)
  {
    start += StageShare[s];
  }
  const double share = StageShare[static_cast<int>(stage)];
  const double overall = std::min(1.0, start + share * std::min(1.0, std::max(0.0, fraction)));
  if (overall < this->Reported)
  {
    return; // a stage skipped ahead earlier: never go back
  }
  this->Reported = overall;
  this->ReportedStage = StageName[static_cast<int>(stage)];
  if (this->Callback)
  {
    this->Callback(overall, this->ReportedStage);
  }
}

void PhaseReporter::heartbeat()
{
  if (this->Callback)
  {
    this->Callback(this->Reported, this->ReportedStage);
  }
}

} // namespace cgmesh
