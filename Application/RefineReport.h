// Statistics of one `cgmesh refine` run: the table printed on stdout and the --stats JSON file.
#ifndef cgmesh_RefineReport_h
#define cgmesh_RefineReport_h

#include "AdaptationMessages.h"
#include "Core/Status.h"

#include <cstdint>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

class vtkCoarseGrainedMeshAdaptation;
class vtkUnstructuredGrid;

namespace cgmesh
{

// Quality of a set of output tets, from the filter's EdgeRatio and MinDihedralAngle arrays;
// percentiles interpolate linearly between ranks (as numpy.percentile does); NaN when empty.
struct QualitySummary
{
  std::int64_t tets = 0;
  double minDihedralAngleMin = 0; // degrees
  double minDihedralAngleP1 = 0;  // 1st percentile, degrees
  double edgeRatioP99 = 0;        // 99th percentile
};

struct RefineStatistics
{
  std::string inputFile;
  std::string outputFile;
  std::int64_t inputPoints = 0;
  std::int64_t inputCells = 0;
  std::int64_t outputPoints = 0;
  std::int64_t outputCells = 0;
  int numberOfColors = 0;
  int numberOfPartitions = 0;
  std::string partitioner;
  std::string materialLabelArrays;  // cell arrays kept as material labels (no region array named)
  std::int64_t interfacePoints = 0; // input points in tets of two or more partitions
  int numberOfThreads = 0;
  int numberOfIterations = 0;
  int iterationsRun = 0;
  bool refinementConverged = false; // the last pass added no point
  std::string sizeArray;            // the size field's array, empty for none
  double sizeGradation = 0;
  double edgesWithinSizeBounds = 0; // share of edges with length / h in [1/sqrt2, sqrt2]
  std::vector<std::int64_t> edgeSizeRatioHistogram; // bins split at 1/2, 1/sqrt2, 1, sqrt2, 2
  double edgeLengthThreshold = 0;                   // the (interface) edge length threshold
  std::string method;                               // "template" or "delaunay"
  double volumeBound = 0;                           // delaunay: the absolute volume bound applied
  std::int64_t delaunayFallbacks = 0;           // partition refinements that fell back to templates
  std::vector<std::int64_t> fallbackPartitions; // their partitions
  std::int64_t tetgenPoints = 0;                // Steiner points TetGen inserted
  std::int64_t tetgenRetries = 0;               // partitions TetGen needed a second attempt for
  std::int64_t tetgenWithoutQualityBound = 0;   // of those, refined without the radius-edge bound
  std::int64_t tetgenRemeshed = 0;              // partitions meshed anew from their kept faces
  std::int64_t sweepRemeshedBoxes = 0;          // Delaunay sweep: boxes meshed anew,
  std::int64_t sweepDroppedPoints = 0;          // the interior points they dropped,
  std::int64_t sweepRemeshFailures = 0;         // and boxes TetGen failed on
  std::int64_t inputRemeshedBoxes = 0;          // sliver-laden input: clusters meshed anew first,
  std::int64_t inputDroppedPoints = 0;          // the interface-round points they dropped,
  std::int64_t inputRemeshFailures = 0;         // and clusters TetGen failed on
  bool partitionByRegion = false;
  int partitionsPerRegion = 1;
  std::string coloring;
  std::vector<std::int64_t> partitionsPerColor; // colour populations, one entry per colour
  std::vector<std::int64_t> cellsPerColor;
  double colorBalance = 0; // largest colour over the mean, in partitions
  bool improveQuality = true;
  int improvementPasses = 2;
  std::int64_t edgeRemovals = 0; // improvement operations
  std::int64_t faceSwaps = 0;
  std::int64_t vertexMoves = 0;
  std::int64_t inputEdgeRemovals = 0; // of those, improving the input before refinement
  std::int64_t inputFaceSwaps = 0;
  std::int64_t inputVertexMoves = 0;
  std::int64_t edgeCollapses = 0;           // coarsening
  std::string compression;                  // of OUT's arrays: "none", "lz4" or "zlib"
  std::vector<double> partitionTaskSeconds; // iteration * partitions + partition
  std::vector<AdaptationWarning> warnings;  // the run's typed warnings, in order
  std::vector<std::int64_t> colorOfPartition;
  QualitySummary allTets;
  QualitySummary interiorTets;      // NearFormerInterface 0
  QualitySummary nearInterfaceTets; // NearFormerInterface 1: touching a former interface vertex
  // (phase, seconds) in pipeline order: the filter's phases, then reading and writing files.
  std::vector<std::pair<std::string, double>> seconds;
};

// Fills counts, colours, partitions, threads, threshold, colouring, colour populations,
// improvement counts and phase seconds from the filter's summary of its last (successful) run,
// and the quality summaries from the output's cell arrays.
void collectFilterStatistics(vtkCoarseGrainedMeshAdaptation* filter, vtkUnstructuredGrid* output,
  RefineStatistics& statistics);

void printStatisticsTable(const RefineStatistics& statistics, std::ostream& stream);

Status writeStatisticsJson(const RefineStatistics& statistics, const std::string& fileName);

// `text` as a quoted, escaped JSON string.
std::string jsonString(const std::string& text);

} // namespace cgmesh

#endif
