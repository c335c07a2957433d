// Statistics of one `cgmesh refine` run: the table printed on stdout and the --stats JSON file.
#ifndef cgmesh_RefineReport_h
#define cgmesh_RefineReport_h

#include "Status.h"

#include <cstdint>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

class vtkUnstructuredGrid;

namespace cgmesh
{

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
  int numberOfThreads = 0;
  int numberOfIterations = 0;
  double edgeLengthThreshold = 0;               // the (interface) edge length threshold
  std::string method;                           // "template" or "delaunay"
  double volumeBound = 0;                       // delaunay: the absolute volume bound applied
  std::int64_t delaunayFallbacks = 0;           // partition refinements that fell back to templates
  std::vector<std::int64_t> fallbackPartitions; // their partitions
  std::int64_t tetgenPoints = 0;                // Steiner points TetGen inserted
  bool partitionByRegion = false;
  int partitionsPerRegion = 1;
  std::string coloring;
  std::vector<std::int64_t> partitionsPerColor; // colour populations, one entry per colour
  std::vector<std::int64_t> cellsPerColor;
  double colorBalance = 0; // largest colour over the mean, in partitions
  // (phase, seconds) in pipeline order: the filter's phases, then reading and writing files.
  std::vector<std::pair<std::string, double>> seconds;
};

// Fills counts, colours, partitions, threads, threshold, colouring, colour populations and phase
// seconds from the filter output's field data (see vtkCoarseGrainedMeshAdaptation).
void collectFilterStatistics(vtkUnstructuredGrid* output, RefineStatistics& statistics);

void printStatisticsTable(const RefineStatistics& statistics, std::ostream& stream);

Status writeStatisticsJson(const RefineStatistics& statistics, const std::string& fileName);

// `text` as a quoted, escaped JSON string.
std::string jsonString(const std::string& text);

} // namespace cgmesh

#endif
