// The parallel colour loop: for each iteration, for each colour in order, all partitions of that
// colour at once: heal from processed neighbours' outboxes, refine, post; then give the new points
// global ids in partition order.
#ifndef cgmesh_ColorLoop_h
#define cgmesh_ColorLoop_h

#include "AdaptationDriver.h"
#include "Improvement/QualityImprover.h"
#include "Partitioning/PartitionGraph.h"
#include "PhaseReporter.h"
#include "Refinement/PartitionRefiner.h"
#include "Refinement/TemplateTable.h"
#include "Refinement/TetGenRefiner.h"

#include <functional>
#include <string>
#include <vector>

namespace cgmesh
{

// What improvement left to do in one partition (see AdaptationState::improvementLeft).
struct ImprovementLeft
{
  bool known = false;
  std::size_t tetCount = 0;      // the partition's tets when this was recorded
  std::vector<std::size_t> tets; // the indices of those that still need improvement
};

// The evolving global state of one adaptation run.
struct AdaptationState
{
  std::vector<PartitionMesh> partitions;
  // Per partition, what the last colour loop's improvement left to do in it, known while the
  // partition stays as it was improved: the improvement sweeps across former interfaces look for
  // work among those tets alone instead of screening every tet again (unknown: every tet).
  std::vector<ImprovementLeft> improvementLeft;
  std::vector<double> coordinates; // all global points
  std::vector<double> sizes;       // with a size field: h of every global point
  PointId inputPointCount = 0;
  std::vector<PointSource> newPointSources; // for global points from inputPointCount on
  std::vector<PointId> movedPoints;         // points quality improvement moved (may repeat)
};

// Delaunay: how a partition calls TetGen; the partition id reaches the worker pool's test hook.
using PartitionTetGenRunner = std::function<std::string(
  int partition, const tetgenio& in, const std::string& switches, tetgenio& out)>;

struct ColorLoopSetup
{
  const std::vector<int>* colorOfPartition = nullptr;
  int numberOfColors = 0;
  int numberOfIterations = 1;
  int threads = 1;
  double squaredThreshold = 0; // template edge threshold, or interface length for Delaunay
  const TemplateTable* templates = nullptr;
  bool orderCornersByCoordinates = false; // see RefinementContext
  RefinementMethod method = RefinementMethod::Template;
  DelaunayParameters delaunay;
  PartitionTetGenRunner runTetGen; // Delaunay: how partitions call TetGen
  bool refine = true;              // false: a sweep of quality improvement only
  // Delaunay: the sweep across former interfaces, whose boxes are meshed anew without the
  // interior points refinement made (remeshPartitionDelaunay) instead of refined.
  bool remeshSweep = false;
  std::int64_t maximumNumberOfCells = 0; // refuse an iteration forecast to exceed it (0: no limit)
  // Refinement: the points the partitions share as the loop starts, when known (the partition
  // graph's); its first pass reads them instead of scanning every tet for them.
  const std::vector<char>* interfaceVertexAtStart = nullptr;
  // Refinement: where the points the partitions share after the last pass go, when wanted.
  std::vector<char>* interfaceVertexAtEnd = nullptr;
  bool improve = false;
  bool sizeField = false; // the points carry the input's size field (AdaptationState::sizes)
  ImprovementParameters improvement;
  // Where the loop's progress goes: `stage`, from `progressStart` to `progressEnd` of it.
  Stage stage = Stage::Refine;
  double progressStart = 0;
  double progressEnd = 1;
};

// Colours the partition graph with the named colouring (see coloringNames()) on `threads`
// threads. A failed parallel task is returned as it is; a colouring that is not proper is an
// Internal error.
Status colorPartitions(const PartitionGraph& graph, const std::string& coloringName, int threads,
  std::vector<int>& colorOfPartition);

// The summary's colour count, populations and balance, from summary.colorOfPartition.
void summarizeColoring(AdaptationSummary& summary);

// Runs all iterations. Sets summary.aborted (and returns success) when options.abortRequested
// says so between two colours. Time goes to the heal, adapt, improve and post phases.
Status runColorLoop(const ColorLoopSetup& setup, const AdaptationOptions& options,
  AdaptationState& state, AdaptationSummary& summary, PhaseReporter& reporter);

} // namespace cgmesh

#endif
