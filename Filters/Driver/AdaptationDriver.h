// The coarse-grained adaptation pipeline: prepare (checks, repairs, the plan), partition,
// partition graph, colouring, the parallel colour loop (heal, adapt, improve, post), the
// improvement sweeps, merge. VTK-free; the VTK filter and the tests call adaptMesh().
#ifndef cgmesh_AdaptationDriver_h
#define cgmesh_AdaptationDriver_h

#include "AdaptationMessages.h"
#include "AdaptationOptions.h"
#include "AdaptationPlan.h"
#include "Core/Status.h"
#include "Core/TetMesh.h"
#include "Merge/MeshMerge.h"
#include "PhaseReporter.h"
#include "Refinement/SizeField.h"

#include <cstdint>
#include <string>
#include <vector>

namespace cgmesh
{

// What a run did, apart from the mesh: the front ends' summary.
struct AdaptationSummary
{
  AdaptationPlan plan;
  int numberOfColors = 0;
  std::int64_t interfacePoints = 0;             // input points in tets of two or more partitions
  std::vector<int> colorOfPartition;            // the refinement colouring
  std::vector<std::int64_t> partitionsPerColor; // colour population, in partitions
  std::vector<std::int64_t> cellsPerColor;      // colour population, in output tets
  double colorBalance = 0;                      // largest colour set / mean (partitions)
  std::int64_t delaunayFallbacks = 0;           // partition refinements that fell back to templates
  std::vector<int> fallbackPartitions;          // their partitions (with repeats across iterations)
  std::int64_t tetgenPoints = 0;                // Steiner points TetGen inserted
  // Refinement passes made; fewer than NumberOfIterations when a pass added no point (the mesh
  // already met the threshold or bound), which sets `refinementConverged`.
  int iterationsRun = 0;
  bool refinementConverged = false;
  // Template passes: partitions not read again, a pass before having found nothing to split in
  // them (refineMembers in ColorLoop.cxx).
  std::int64_t skippedPartitionReads = 0;
  std::int64_t tetgenRetries = 0; // partition refinements whose first TetGen call failed
  std::int64_t tetgenWithoutQualityBound = 0; // of those, refined by TetGen without q
  std::int64_t tetgenRemeshed = 0; // partitions TetGen meshed anew from their kept faces (slivers)
  // The Delaunay sweep across former interfaces (remeshAcrossFormerInterfaces): boxes meshed
  // anew, the interior points they dropped, and boxes where TetGen failed (left as refined).
  std::int64_t sweepRemeshedBoxes = 0;
  std::int64_t sweepDroppedPoints = 0;
  std::int64_t sweepRemeshFailures = 0;
  // Delaunay with ImproveInput on a sliver-laden input: the clusters of slivers meshed anew
  // before refinement, and those where TetGen failed, left as they were (InputImprovement.h).
  std::int64_t inputRemeshedBoxes = 0;
  std::int64_t inputDroppedPoints = 0; // interface-round points inside the clusters, dropped
  std::int64_t inputRemeshFailures = 0;
  // The input was meshed anew as a whole with its tagged triangles free to split and merge
  // (AdaptationOptions::surfaceClasses): their children are found by position.
  bool boundaryRetriangulated = false;
  bool concurrentTetGen = false;    // TetGen calls overlapped (in worker processes)
  std::int64_t reorientedTets = 0;  // inverted input tets that were turned around
  std::int64_t gluedPoints = 0;     // copies of matching faces' corners merged into one point
  std::int64_t keptApartPoints = 0; // input points left distinct from a coincident one
  std::int64_t edgeRemovals = 0;    // quality improvement operations
  std::int64_t edgeCollapses = 0;   // coarsening
  std::int64_t faceSwaps = 0;
  std::int64_t vertexMoves = 0;
  // Of those, the ones improving the input before refinement (ImproveInput).
  std::int64_t inputEdgeRemovals = 0;
  std::int64_t inputFaceSwaps = 0;
  std::int64_t inputVertexMoves = 0;
  std::int64_t poorTets = 0; // tets below the improvement target when first looked at
  EdgeSizeReport edgeSizes;  // with a size field: the output's edges against it
  // Seconds each partition's heal and refinement took, per iteration: entry
  // iteration * plan.partitions + partition (the data for makespan models).
  std::vector<double> partitionTaskSeconds;
  bool aborted = false;
  PhaseSeconds seconds;
  double totalSeconds = 0;
  std::vector<AdaptationWarning> warnings;
};

struct AdaptationResult
{
  TetMesh mesh;                        // merged, conforming, no unused points
  UnfilledVector<CellId> parentCell;   // per output tet: the input tet it came from
  UnfilledVector<int> partitionOfCell; // per output tet
  UnfilledVector<int> colorOfCell;     // per output tet
  PointProvenance provenance;          // per output point, over input point ids (if asked for)
  // Per output tet: 1 when it touches a vertex that lay on an interface between refinement
  // partitions (to compare quality near former interfaces with the interior).
  std::vector<char> nearFormerInterface;
  // With a size field (mesh.sizes): per output tet, its longest edge over its corners' mean size.
  std::vector<double> edgeLengthRatio;
  AdaptationSummary summary;
};

// Refines `input` (left untouched; see InputPreparation.h for the checks and repairs). On failure
// the Status carries the kind and a one-line message, and `result` holds no mesh; the summary
// keeps the plan, the warnings and the seconds spent.
Status adaptMesh(const TetMesh& input, const AdaptationOptions& options, AdaptationResult& result);

} // namespace cgmesh

#endif
