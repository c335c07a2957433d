// The plan of one run: the options resolved against the input once, before any work. Everything
// later stages need to know about the settings is here; nothing downstream changes it.
#ifndef cgmesh_AdaptationPlan_h
#define cgmesh_AdaptationPlan_h

#include "AdaptationMessages.h"
#include "AdaptationOptions.h"
#include "Core/Status.h"
#include "Core/TetMesh.h"

#include <array>
#include <vector>

namespace cgmesh
{

struct AdaptationPlan
{
  int threads = 1;    // 0 in the options means every core
  int partitions = 1; // refinement partitions (after clamping, or by region)
  PartitionerKind partitioner = PartitionerKind::Metis; // never Automatic; METIS by region
  double edgeLengthThreshold = 0;     // template threshold, or Delaunay's interface edge length
  bool sizeField = false;             // templates split against the input's size field instead
  std::vector<int> refinementRegions; // refine only tets of these regions (empty: all)
  bool hasRefinementBox = false;      // refine only tets meeting refinementBox
  std::array<double, 6> refinementBox = {};
  bool restricted() const { return !refinementRegions.empty() || hasRefinementBox; }
  double volumeBound = 0;            // Delaunay: the absolute volume bound; 0 for templates
  int boxesPerAxis = 1;              // improvement sweeps: boxes along each axis
  double improvementVolumeBound = 0; // improvement must not make tets larger than this (0: none)
  // Delaunay with a volume bound on a small output: a sliver-laden input meshed anew as a whole
  // is refined to the bound in that same TetGen call, and the refinement passes only improve.
  bool wholeInputCallRefines = false;
};

// Checks `options` on their own and against the raw input's shape (ids in range, one region per
// tet); InvalidInput or InvalidOption on failure.
Status checkOptionsAndInput(const TetMesh& input, const AdaptationOptions& options);

// Resolves `options` against the prepared (repaired) input. Appends a warning when the partition
// count had to be reduced.
AdaptationPlan resolvePlan(
  const TetMesh& input, const AdaptationOptions& options, std::vector<AdaptationWarning>& warnings);

// The input's mean tet edge length (over the six edges of every tet) and mean tet volume: what
// EdgeLengthFactor and VolumeFactor scale. The same for any thread count.
double meanTetEdgeLength(const TetMesh& mesh, int threads = 1);
double meanTetVolume(const TetMesh& mesh, int threads = 1);

} // namespace cgmesh

#endif
