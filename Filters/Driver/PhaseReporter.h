// Time and progress of one adaptation run. Time is charged to phases: entering a phase charges
// the seconds since the last change to the phase that was running, so the phases add up to the
// run and nothing is counted twice. Progress moves through stages, each with a fixed share of
// [0, 1]; the fraction reported never decreases.
#ifndef cgmesh_PhaseReporter_h
#define cgmesh_PhaseReporter_h

#include "Core/Stopwatch.h"

#include <array>
#include <functional>

namespace cgmesh
{

enum class Phase
{
  Prepare,   // checks, repairs, the plan, distributing tets to partitions
  Partition, // METIS, or the cut along regions
  Graph,     // partition graph
  Color,     // colouring
  Heal,      // interface vertices of each pass, posting a colour's splits for later colours
  Adapt,     // refining partitions, healing from the posted splits
  Improve,   // quality improvement in partitions and both box sweeps (regrouping included)
  Post,      // numbering a colour's new points
  Merge,     // joining partitions, point provenance
  Count
};

enum class Stage
{
  Prepare,
  Partition,    // partitioning, graph and colouring
  ImproveInput, // improving the input before template refinement
  Refine,       // the colour loop over all iterations
  Sweep,        // the improvement sweeps across former interfaces
  Merge,
  Count
};

// Seconds per phase; their sum is the run's time up to the last phase change.
struct PhaseSeconds
{
  std::array<double, static_cast<int>(Phase::Count)> seconds = {};

  double& operator[](Phase phase) { return this->seconds[static_cast<int>(phase)]; }
  double operator[](Phase phase) const { return this->seconds[static_cast<int>(phase)]; }
  double total() const;
};

const char* phaseName(Phase phase); // "partition", "heal", ... (the stats file's keys)

class PhaseReporter
{
public:
  using ProgressCallback = std::function<void(double fraction, const char* stage)>;

  explicit PhaseReporter(ProgressCallback callback)
    : Callback(std::move(callback))
  {
  }

  // Charges the time since the last change to the running phase, then runs `phase`.
  void enter(Phase phase);
  // Charges the running phase and stops the clock until the next enter().
  void stop();

  // Reports `fraction` (0..1) of `stage` done.
  void progress(Stage stage, double fraction);
  // Reports the last progress again: while a long step runs, the front end gets a chance to show
  // it is alive and to take an abort.
  void heartbeat();

  const PhaseSeconds& seconds() const { return this->Seconds; }

private:
  ProgressCallback Callback;
  PhaseSeconds Seconds;
  Stopwatch Clock;
  Phase Running = Phase::Count; // none
  double Reported = 0;
  const char* ReportedStage = "preparing";
};

} // namespace cgmesh

#endif
