// Delaunay refinement of one partition: its interface and material-interface edges are first split
// by templates (so neighbours can heal them through the outbox), then TetGen refines the interior
// with every boundary and material-interface face kept as it is (switches r, Y, q, a).
// A TetGen failure (a thrown int, or output that does not validate) never loses the partition: it
// falls back to template refinement of the interior edges.
#ifndef cgmesh_TetGenRefiner_h
#define cgmesh_TetGenRefiner_h

#include "Refinement/PartitionRefiner.h"

#include <functional>
#include <string>

class tetgenio;

namespace cgmesh
{

struct DelaunayParameters
{
  double maximumVolume = 0;     // TetGen's volume bound (switch a)
  double radiusEdgeRatio = 2;   // TetGen's radius-edge quality bound (switch q)
  bool simulateFailure = false; // behave as if TetGen had failed (tests of the fallback)
};

// The edge length up to which templates refine interfaces for a volume bound: the edge of the
// regular tetrahedron of that volume, (6 sqrt(2) V)^(1/3).
double interfaceEdgeLengthForVolume(double maximumVolume);

// About how many tets TetGen makes of `volume` under the bound: its tets average about a third
// of the bound (measured on cubes and FinFETs). Used by the size guard and the partition count.
double forecastDelaunayTets(double volume, double maximumVolume);

// Runs TetGen with the given switches on `in`, filling `out`; returns an empty string on success,
// else why it failed. The driver runs the calls in worker processes (see TetGenWorkers.h). A
// call stopped for taking too long returns a reason that starts with TetGenTimeLimitReason: no
// further attempt is made on that partition.
constexpr const char* TetGenTimeLimitReason = "TetGen took longer than";
using TetGenRunner =
  std::function<std::string(const tetgenio& in, const std::string& switches, tetgenio& out)>;

struct DelaunayOutcome
{
  bool fellBack = false;            // TetGen failed; the partition was template-refined instead
  bool retried = false;             // the first TetGen call failed, a second attempt was made
  bool withoutQualityBound = false; // refined by the last attempt, without the radius-edge bound
  std::string reason;               // why, when it fell back
  std::int64_t tetgenPoints = 0;    // Steiner points TetGen inserted
};

// `context.squaredThreshold` must hold the squared interface edge length.
Status refinePartitionDelaunay(PartitionMesh& partition, const RefinementContext& context,
  const EdgeMidpointMap& received, const DelaunayParameters& parameters,
  const TetGenRunner& runTetGen, PartitionRefinement& refinement, DelaunayOutcome& outcome);

} // namespace cgmesh

#endif
