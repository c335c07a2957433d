// The coarse-grained adaptation pipeline: partition, partition graph, colouring, the parallel
// colour loop (heal, adapt, post), merge. VTK-free; the VTK filter and the tests call adaptMesh().
#ifndef cgmesh_AdaptationDriver_h
#define cgmesh_AdaptationDriver_h

#include "Merge/MeshMerge.h"
#include "Core/Status.h"
#include "Core/TetMesh.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace cgmesh
{

enum class RefinementMethod
{
  Template, // split long edges by templates
  Delaunay  // templates on interfaces, TetGen inside partitions
};

struct AdaptationOptions
{
  RefinementMethod method = RefinementMethod::Template;
  int numberOfPartitions = 1024; // clamped (with a warning) when the mesh is too small
  int numberOfIterations = 1;    // full passes of the colour loop
  double maximumEdgeLength = 0;  // absolute split threshold; used when > 0
  double edgeLengthFactor = 0.5; // else threshold = factor * mean input edge length
  int numberOfThreads = 0;       // 0 = all available cores
  // Refuse (before refining) an iteration forecast to produce more tets than this; 0: no limit.
  std::int64_t maximumNumberOfCells = 100000000;
  // Delaunay: TetGen's volume bound, absolute when > 0, else volumeFactor * mean input tet
  // volume; interface edges are split by templates up to the edge length of a regular tet of
  // that volume.
  double maximumVolume = 0;
  double volumeFactor = 0.1;
  double radiusEdgeRatio = 2.0; // Delaunay: TetGen's radius-edge quality bound (q)
  // Delaunay: run TetGen calls one at a time even where they could overlap (a reference for
  // stress tests, and a way out should a TetGen build misbehave).
  bool serializeTetGen = false;
  // Partitions whose TetGen call is made to fail, to exercise the fallback (tests).
  std::vector<int> simulateTetGenFailureIn;
  // After refinement: edge removal, face swaps and smoothing inside each partition, then a second
  // sweep over shifted partitions so that former interfaces are improved too.
  bool improveQuality = true;
  int improvementPasses = 2;
  // See coloringNames(): greedy, greedy-lu, iterative, recoloring.
  std::string coloring = "greedy-lu";
  bool partitionByRegion = false; // cut along regions (needs input regions) instead of METIS
  int partitionsPerRegion = 1;    // with partitionByRegion: METIS parts within each region

  // Called on the calling thread only: fraction in [0, 1] and a short stage name.
  std::function<void(double fraction, const char* stage)> progress;
  // Polled on the calling thread between colours; returning true aborts the run.
  std::function<bool()> abortRequested;
};

// Wall-clock seconds per phase. heal, adapt and post add up the per-colour parallel loops.
struct PhaseSeconds
{
  double partition = 0; // METIS on the dual graph
  double graph = 0;     // partition graph
  double color = 0;     // colouring
  double heal = 0;      // reading neighbours' outboxes
  double adapt = 0;     // template refinement, posting outboxes
  double post = 0;      // global numbering of new points after each colour
  double improve = 0;   // quality improvement, both sweeps
  double merge = 0;     // joining partitions, point provenance
  double total = 0;
};

struct AdaptationResult
{
  TetMesh mesh;                     // merged, conforming, no unused points
  std::vector<CellId> parentCell;   // per output tet: the input tet it came from
  std::vector<int> partitionOfCell; // per output tet
  std::vector<int> colorOfCell;     // per output tet
  PointProvenance provenance;       // per output point, over input point ids
  int numberOfPartitions = 0;       // after clamping
  int numberOfColors = 0;
  int numberOfThreads = 0;             // threads actually used
  double edgeLengthThreshold = 0;      // the absolute threshold that was applied
  std::int64_t healedSplits = 0;       // interface splits taken over from a neighbour's outbox
  std::int64_t createdSplits = 0;      // edge splits made (each new point once)
  double volumeBound = 0;              // Delaunay: the absolute volume bound that was applied
  std::int64_t delaunayFallbacks = 0;  // partition refinements that fell back to templates
  std::vector<int> fallbackPartitions; // their partitions (with repeats across iterations)
  std::int64_t tetgenPoints = 0;       // Steiner points TetGen inserted
  bool concurrentTetGen = false;       // TetGen calls overlapped (in separate worker processes)
  std::int64_t reorientedTets = 0;     // inverted input tets that were turned around
  std::int64_t mergedPoints = 0;       // input points merged into a coincident one
  // Seconds each partition's heal and refinement took, per iteration: entry
  // iteration * numberOfPartitions + partition (the data for makespan models).
  std::vector<double> partitionTaskSeconds;
  std::vector<int> colorOfPartition;            // the refinement colouring
  std::vector<std::int64_t> partitionsPerColor; // colour population, in partitions
  std::vector<std::int64_t> cellsPerColor;      // colour population, in output tets
  double colorBalance = 0;                      // largest colour set / mean (partitions)
  std::int64_t edgeRemovals = 0;                // quality improvement operations
  std::int64_t faceSwaps = 0;
  std::int64_t vertexMoves = 0;
  std::int64_t poorTets = 0; // tets below the improvement target when first looked at
  // Per output tet: 1 when it touches a vertex that lay on an interface between refinement
  // partitions (to compare quality near former interfaces with the interior).
  std::vector<char> nearFormerInterface;
  bool aborted = false;
  PhaseSeconds seconds;
  std::vector<std::string> warnings;
};

// Refines `input` (left untouched; see InputPreparation.h for the checks and repairs). On failure
// the Status carries a one-line message and `result` holds no mesh.
Status adaptMesh(const TetMesh& input, const AdaptationOptions& options, AdaptationResult& result);

} // namespace cgmesh

#endif
