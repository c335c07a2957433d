#include "RefineReport.h"

#include "AdaptationDriver.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCoarseGrainedMeshAdaptation.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <utility>

namespace cgmesh
{

namespace
{

// "a b c" for the table, "[a, b, c]" for JSON.
std::string joinValues(const std::vector<std::int64_t>& values, const char* separator)
{
  std::ostringstream joined;
  for (size_t index = 0; index < values.size(); ++index)
  {
    joined << (index ? separator : "") << values[index];
  }
  return joined.str();
}

// Values held in one or more vectors, ranked together.
using ValueParts = std::vector<const std::vector<double>*>;

std::size_t valueCount(const ValueParts& parts)
{
  std::size_t count = 0;
  for (const std::vector<double>* part : parts)
  {
    count += part->size();
  }
  return count;
}

// The values ranked `rank` and `rank + 1` from the smallest (0-based) of all `parts` together.
// Selecting over all of them cost about 40 ms per 6.5 M values, and joining the groups into one
// copy as much: the 1st and 99th percentiles lie among the few values beyond a sample's order
// statistic, so only those are gathered and ranked when they are enough to hold both ranks (they
// are but for freak samples; then all values are).
std::pair<double, double> valuesAtRanks(const ValueParts& parts, std::size_t rank)
{
  const std::size_t count = valueCount(parts);
  const bool fromTop = rank >= count / 2;
  // How many values the near side must hold: up to rank + 1 from the bottom, or from `rank` to
  // the top.
  const std::size_t needed = fromTop ? count - rank : rank + 2;
  constexpr std::size_t SampleSize = 65536;
  std::vector<double> ranked;
  if (count > 4 * SampleSize && needed < count / 8)
  {
    const std::size_t stride = count / SampleSize;
    std::vector<double> sample;
    sample.reserve(count / stride + parts.size());
    for (const std::vector<double>* part : parts)
    {
      for (std::size_t i = 0; i < part->size(); i += stride)
      {
        sample.push_back((*part)[i]);
      }
    }
    // Twice the expected share, and some: a bound that leaves too few values is rare.
    const std::size_t sampleRank =
      std::min(sample.size() - 1, 2 * (needed * sample.size() / count) + 64);
    const std::size_t at = fromTop ? sample.size() - 1 - sampleRank : sampleRank;
    std::nth_element(sample.begin(), sample.begin() + at, sample.end());
    const double bound = sample[at];
    ranked.reserve(2 * (sampleRank + 1) * stride);
    for (const std::vector<double>* part : parts)
    {
      for (double value : *part)
      {
        if (fromTop ? value >= bound : value <= bound)
        {
          ranked.push_back(value);
        }
      }
    }
  }
  // Every value on the near side of the bound was gathered, so ranks counted from that side are
  // the same among them as among all values.
  std::size_t offset = 0;
  if (ranked.size() >= needed)
  {
    offset = fromTop ? count - ranked.size() : 0;
  }
  else
  {
    ranked.clear();
    ranked.reserve(count);
    for (const std::vector<double>* part : parts)
    {
      ranked.insert(ranked.end(), part->begin(), part->end());
    }
  }
  const std::size_t lower = rank - offset;
  std::nth_element(ranked.begin(), ranked.begin() + lower, ranked.end());
  const double lowerValue = ranked[lower];
  if (lower + 1 >= ranked.size())
  {
    return { lowerValue, lowerValue };
  }
  // After nth_element every value past `lower` is at least lowerValue: the next rank is their
  // minimum.
  return { lowerValue, *std::min_element(ranked.begin() + lower + 1, ranked.end()) };
}

// The p-th percentile of all `parts` together, interpolating linearly between the two nearest
// ranks like numpy.percentile's default; NaN when empty.
double percentile(const ValueParts& parts, double p)
{
  const std::size_t count = valueCount(parts);
  if (count == 0)
    return std::numeric_limits<double>::quiet_NaN();
  const double position = p / 100.0 * static_cast<double>(count - 1);
  const auto lower = static_cast<std::size_t>(std::floor(position));
  const std::pair<double, double> ranks = valuesAtRanks(parts, lower);
  return ranks.first + (position - static_cast<double>(lower)) * (ranks.second - ranks.first);
}

QualitySummary summarizeQuality(const ValueParts& angles, const ValueParts& edgeRatios)
{
  QualitySummary summary;
  summary.tets = static_cast<std::int64_t>(valueCount(angles));
  summary.minDihedralAngleMin = std::numeric_limits<double>::quiet_NaN();
  for (const std::vector<double>* part : angles)
  {
    if (!part->empty())
    {
      const double least = *std::min_element(part->begin(), part->end());
      summary.minDihedralAngleMin = std::isnan(summary.minDihedralAngleMin)
        ? least
        : std::min(summary.minDihedralAngleMin, least);
    }
  }
  summary.minDihedralAngleP1 = percentile(angles, 1.0);
  summary.edgeRatioP99 = percentile(edgeRatios, 99.0);
  return summary;
}

// All tets, and the tets split by the NearFormerInterface cell array (all interior without it).
void collectQualitySummaries(vtkUnstructuredGrid* output, RefineStatistics& statistics)
{
  vtkCellData* cellData = output->GetCellData();
  vtkDataArray* angleArray = cellData->GetArray("MinDihedralAngle");
  vtkDataArray* edgeRatioArray = cellData->GetArray("EdgeRatio");
  vtkDataArray* nearArray = cellData->GetArray("NearFormerInterface");
  if (!angleArray || !edgeRatioArray)
    return;
  // Read through plain pointers where the arrays are the filter's own doubles and bytes: the
  // virtual calls per value cost more than the summaries.
  const auto valuesOf = [](vtkDataArray* array, std::vector<double>& copy) -> const double*
  {
    if (auto* doubles = vtkDoubleArray::SafeDownCast(array))
    {
      return doubles->GetPointer(0);
    }
    copy.resize(static_cast<std::size_t>(array->GetNumberOfTuples()));
    for (vtkIdType id = 0; id < array->GetNumberOfTuples(); ++id)
    {
      copy[id] = array->GetComponent(id, 0);
    }
    return copy.data();
  };
  std::vector<double> angleCopy, edgeRatioCopy, nearCopy;
  const double* angle = valuesOf(angleArray, angleCopy);
  const double* edgeRatio = valuesOf(edgeRatioArray, edgeRatioCopy);
  auto* nearBytes = vtkUnsignedCharArray::SafeDownCast(nearArray);
  const unsigned char* nearByte = nearBytes ? nearBytes->GetPointer(0) : nullptr;
  const double* nearValue = nearArray && !nearBytes ? valuesOf(nearArray, nearCopy) : nullptr;
  const auto isNear = [&](vtkIdType cellId)
  {
    return nearByte ? nearByte[cellId] != 0 : nearValue && nearValue[cellId] != 0;
  };
  vtkUnsignedCharArray* typeArray = output->GetCellTypesArray();
  const unsigned char* type = typeArray ? typeArray->GetPointer(0) : nullptr;
  const vtkIdType cells = output->GetNumberOfCells();
  std::size_t tetsOf[2] = { 0, 0 };
  for (vtkIdType cellId = 0; type && cellId < cells; ++cellId)
  {
    // Tagged triangles have no tet quality.
    tetsOf[isNear(cellId)] += type[cellId] == VTK_TETRA;
  }
  std::vector<double> angles[2];
  std::vector<double> edgeRatios[2];
  for (int near = 0; near < 2; ++near)
  {
    angles[near].reserve(tetsOf[near]);
    edgeRatios[near].reserve(tetsOf[near]);
  }
  for (vtkIdType cellId = 0; type && cellId < cells; ++cellId)
  {
    if (type[cellId] != VTK_TETRA)
      continue;
    const int near = isNear(cellId);
    angles[near].push_back(angle[cellId]);
    edgeRatios[near].push_back(edgeRatio[cellId]);
  }
  statistics.allTets =
    summarizeQuality({ &angles[0], &angles[1] }, { &edgeRatios[0], &edgeRatios[1] });
  statistics.interiorTets = summarizeQuality({ &angles[0] }, { &edgeRatios[0] });
  statistics.nearInterfaceTets = summarizeQuality({ &angles[1] }, { &edgeRatios[1] });
}

double phaseSeconds(const RefineStatistics& statistics, const std::string& phase)
{
  for (const auto& entry : statistics.seconds)
  {
    if (entry.first == phase)
      return entry.second;
  }
  return 0.0;
}

// Improve seconds over the filter's total seconds, 0 when the total is 0.
double improveShare(const RefineStatistics& statistics)
{
  const double total = phaseSeconds(statistics, "total");
  return total > 0 ? phaseSeconds(statistics, "improve") / total : 0.0;
}

void printImprovement(const RefineStatistics& statistics, std::ostream& stream)
{
  stream << std::setw(24) << "improvement"
         << (statistics.improveQuality
                ? "on, " + std::to_string(statistics.improvementPasses) + " passes"
                : std::string("off"))
         << "\n"
         << std::setw(24) << "edge removals" << statistics.edgeRemovals << "\n"
         << std::setw(24) << "face swaps" << statistics.faceSwaps << "\n"
         << std::setw(24) << "vertex moves" << statistics.vertexMoves << "\n"
         << std::setw(24) << "of them on the input" << statistics.inputEdgeRemovals
         << " edge removals, " << statistics.inputFaceSwaps << " face swaps, "
         << statistics.inputVertexMoves << " vertex moves\n"
         << std::setw(24) << "edge collapses" << statistics.edgeCollapses << "\n"
         << std::setw(24) << "improve seconds" << std::fixed << std::setprecision(4)
         << phaseSeconds(statistics, "improve") << std::defaultfloat << " (" << std::setprecision(3)
         << 100.0 * improveShare(statistics) << " % of total)\n";
}

// "3 (delaunay-fallback 2, partitions-reduced 1)": the warnings by kind, in order of first use.
void printWarningCounts(const RefineStatistics& statistics, std::ostream& stream)
{
  std::vector<std::pair<WarningKind, int>> counts;
  for (const AdaptationWarning& warning : statistics.warnings)
  {
    auto found = std::find_if(counts.begin(), counts.end(),
      [&warning](const auto& entry) { return entry.first == warning.kind; });
    if (found == counts.end())
      counts.emplace_back(warning.kind, 1);
    else
      ++found->second;
  }
  stream << std::setw(24) << "warnings" << statistics.warnings.size();
  for (std::size_t index = 0; index < counts.size(); ++index)
  {
    stream << (index ? ", " : " (") << warningKindName(counts[index].first) << " "
           << counts[index].second << (index + 1 == counts.size() ? ")" : "");
  }
  stream << "\n";
}

void printQualityRow(const char* name, const QualitySummary& summary, std::ostream& stream)
{
  stream << std::setw(24) << name << std::right << std::setw(10) << summary.tets;
  if (summary.tets == 0)
  {
    stream << std::setw(18) << "-" << std::setw(18) << "-" << std::setw(16) << "-";
  }
  else
  {
    stream << std::fixed << std::setprecision(3) << std::setw(18) << summary.minDihedralAngleMin
           << std::setw(18) << summary.minDihedralAngleP1 << std::setw(16) << summary.edgeRatioP99
           << std::defaultfloat;
  }
  stream << std::left << "\n";
}

void printQualitySummaries(const RefineStatistics& statistics, std::ostream& stream)
{
  stream << "\n"
         << std::setw(24) << "quality" << std::right << std::setw(10) << "tets" << std::setw(18)
         << "min dihedral min" << std::setw(18) << "min dihedral p1" << std::setw(16)
         << "edge ratio p99" << std::left << "\n";
  printQualityRow("all", statistics.allTets, stream);
  printQualityRow("interior", statistics.interiorTets, stream);
  printQualityRow("near former interfaces", statistics.nearInterfaceTets, stream);
}

// A JSON number, or null for NaN (an empty set of tets).
std::string jsonNumber(double value)
{
  if (std::isnan(value))
    return "null";
  std::ostringstream text;
  text << std::setprecision(17) << value;
  return text.str();
}

std::string qualityJson(const QualitySummary& summary)
{
  const bool empty = summary.tets == 0;
  const double none = std::numeric_limits<double>::quiet_NaN();
  return "{\"tets\": " + std::to_string(summary.tets) +
    ", \"minDihedralAngleMin\": " + jsonNumber(empty ? none : summary.minDihedralAngleMin) +
    ", \"minDihedralAngleP1\": " + jsonNumber(empty ? none : summary.minDihedralAngleP1) +
    ", \"edgeRatioP99\": " + jsonNumber(empty ? none : summary.edgeRatioP99) + "}";
}

void writeImprovementJson(const RefineStatistics& statistics, std::ostream& file)
{
  file << "  \"improvement\": {\"enabled\": " << (statistics.improveQuality ? "true" : "false")
       << ", \"passes\": " << statistics.improvementPasses
       << ", \"edgeRemovals\": " << statistics.edgeRemovals
       << ", \"faceSwaps\": " << statistics.faceSwaps
       << ", \"vertexMoves\": " << statistics.vertexMoves
       << ", \"input\": {\"edgeRemovals\": " << statistics.inputEdgeRemovals
       << ", \"faceSwaps\": " << statistics.inputFaceSwaps
       << ", \"vertexMoves\": " << statistics.inputVertexMoves << "}"
       << ", \"edgeCollapses\": " << statistics.edgeCollapses
       << ", \"seconds\": " << jsonNumber(phaseSeconds(statistics, "improve"))
       << ", \"shareOfTotal\": " << jsonNumber(improveShare(statistics)) << "},\n"
       << "  \"quality\": {\"all\": " << qualityJson(statistics.allTets)
       << ",\n              \"interior\": " << qualityJson(statistics.interiorTets)
       << ",\n              \"nearFormerInterfaces\": " << qualityJson(statistics.nearInterfaceTets)
       << "},\n";
}

} // namespace

std::string jsonString(const std::string& text)
{
  std::ostringstream escaped;
  escaped << '"';
  for (const char character : text)
  {
    if (character == '"' || character == '\\')
      escaped << '\\' << character;
    else if (static_cast<unsigned char>(character) < 0x20)
      escaped << "\\u" << std::hex << std::setw(4) << std::setfill('0')
              << static_cast<int>(character) << std::dec;
    else
      escaped << character;
  }
  escaped << '"';
  return escaped.str();
}

void collectFilterStatistics(
  vtkCoarseGrainedMeshAdaptation* filter, vtkUnstructuredGrid* output, RefineStatistics& statistics)
{
  const AdaptationSummary& summary = *filter->GetLastSummary();
  statistics.outputPoints = output->GetNumberOfPoints();
  statistics.outputCells = output->GetNumberOfCells();
  statistics.numberOfColors = summary.numberOfColors;
  statistics.numberOfPartitions = summary.plan.partitions;
  statistics.partitioner =
    vtkCoarseGrainedMeshAdaptation::PartitionerToName(static_cast<int>(summary.plan.partitioner));
  statistics.materialLabelArrays = filter->GetMaterialLabelArrays();
  statistics.interfacePoints = summary.interfacePoints;
  statistics.numberOfThreads = summary.plan.threads;
  statistics.edgeLengthThreshold = summary.plan.edgeLengthThreshold;
  statistics.iterationsRun = summary.iterationsRun;
  statistics.refinementConverged = summary.refinementConverged;
  if (summary.plan.sizeField)
  {
    statistics.sizeArray = filter->GetSizeArrayName() ? filter->GetSizeArrayName() : "";
    statistics.sizeGradation = filter->GetSizeGradation();
    statistics.edgesWithinSizeBounds = summary.edgeSizes.shareWithinBounds;
    statistics.edgeSizeRatioHistogram.assign(
      summary.edgeSizes.histogram.begin(), summary.edgeSizes.histogram.end());
  }
  statistics.coloring = filter->GetColoringAlgorithmName();
  statistics.method = filter->GetMethodName();
  statistics.volumeBound = summary.plan.volumeBound;
  statistics.delaunayFallbacks = summary.delaunayFallbacks;
  statistics.fallbackPartitions.assign(
    summary.fallbackPartitions.begin(), summary.fallbackPartitions.end());
  statistics.tetgenPoints = summary.tetgenPoints;
  statistics.tetgenRetries = summary.tetgenRetries;
  statistics.tetgenWithoutQualityBound = summary.tetgenWithoutQualityBound;
  statistics.tetgenRemeshed = summary.tetgenRemeshed;
  statistics.sweepRemeshedBoxes = summary.sweepRemeshedBoxes;
  statistics.sweepDroppedPoints = summary.sweepDroppedPoints;
  statistics.sweepRemeshFailures = summary.sweepRemeshFailures;
  statistics.inputRemeshedBoxes = summary.inputRemeshedBoxes;
  statistics.inputDroppedPoints = summary.inputDroppedPoints;
  statistics.inputRemeshFailures = summary.inputRemeshFailures;
  statistics.partitionsPerColor = summary.partitionsPerColor;
  statistics.cellsPerColor = summary.cellsPerColor;
  statistics.colorBalance = summary.colorBalance;
  statistics.edgeRemovals = summary.edgeRemovals;
  statistics.faceSwaps = summary.faceSwaps;
  statistics.vertexMoves = summary.vertexMoves;
  statistics.inputEdgeRemovals = summary.inputEdgeRemovals;
  statistics.inputFaceSwaps = summary.inputFaceSwaps;
  statistics.inputVertexMoves = summary.inputVertexMoves;
  statistics.edgeCollapses = summary.edgeCollapses;
  statistics.partitionTaskSeconds = summary.partitionTaskSeconds;
  statistics.warnings = summary.warnings;
  statistics.colorOfPartition.assign(
    summary.colorOfPartition.begin(), summary.colorOfPartition.end());
  collectQualitySummaries(output, statistics);
  for (int phase = 0; phase < static_cast<int>(Phase::Count); ++phase)
  {
    statistics.seconds.emplace_back(
      phaseName(static_cast<Phase>(phase)), summary.seconds[static_cast<Phase>(phase)]);
  }
  statistics.seconds.emplace_back("input", filter->GetLastInputSeconds());
  statistics.seconds.emplace_back("output", filter->GetLastOutputSeconds());
  statistics.seconds.emplace_back("quality", filter->GetLastQualitySeconds());
  statistics.seconds.emplace_back("total", filter->GetLastTotalSeconds());
}

void printStatisticsTable(const RefineStatistics& statistics, std::ostream& stream)
{
  stream << std::left << std::setw(24) << "input points" << statistics.inputPoints << "\n"
         << std::setw(24) << "input cells" << statistics.inputCells << "\n"
         << std::setw(24) << "output points" << statistics.outputPoints << "\n"
         << std::setw(24) << "output cells" << statistics.outputCells << "\n"
         << std::setw(24) << "partitions" << statistics.numberOfPartitions
         << (statistics.partitionByRegion
                ? " (by region, " + std::to_string(statistics.partitionsPerRegion) + " per region)"
                : " (" + statistics.partitioner + ")")
         << "\n";
  if (!statistics.materialLabelArrays.empty())
  {
    stream << std::setw(24) << "material labels" << statistics.materialLabelArrays
           << " (integer cell arrays whose interfaces are kept; --region-array names one)\n";
  }
  stream << std::setw(24) << "interface points" << statistics.interfacePoints << "\n"
         << std::setw(24) << "coloring" << statistics.coloring << "\n"
         << std::setw(24) << "colors" << statistics.numberOfColors << "\n"
         << std::setw(24) << "partitions per color"
         << joinValues(statistics.partitionsPerColor, " ") << "\n"
         << std::setw(24) << "cells per color" << joinValues(statistics.cellsPerColor, " ") << "\n"
         << std::setw(24) << "color balance" << std::setprecision(4) << statistics.colorBalance
         << "\n"
         << std::setw(24) << "threads" << statistics.numberOfThreads << "\n"
         << std::setw(24) << "iterations" << statistics.iterationsRun << " of "
         << statistics.numberOfIterations
         << (statistics.refinementConverged ? " (converged: the last pass added no point)" : "")
         << (statistics.method == "delaunay" && !statistics.sizeArray.empty()
                ? " (Delaunay to a size field: one pass, TetGen meets the field in it)"
                : "")
         << "\n"
         << std::setw(24) << "method" << statistics.method << "\n";
  if (statistics.sizeArray.empty())
  {
    stream << std::setw(24) << "edge length threshold" << std::setprecision(6)
           << statistics.edgeLengthThreshold << "\n";
  }
  else
  {
    stream << std::setw(24) << "size field" << statistics.sizeArray << " (gradation "
           << statistics.sizeGradation << ")\n"
           << std::setw(24) << "edges within size" << std::setprecision(4)
           << 100 * statistics.edgesWithinSizeBounds << "% in [h/sqrt2, sqrt2 h]; by length/h "
           << joinValues(statistics.edgeSizeRatioHistogram, " ") << "\n";
  }
  if (statistics.method == "delaunay")
  {
    stream << std::setw(24) << "volume bound" << statistics.volumeBound << "\n"
           << std::setw(24) << "tetgen points" << statistics.tetgenPoints << "\n"
           << std::setw(24) << "tetgen retries" << statistics.tetgenRetries << "\n"
           << std::setw(24) << "tetgen without q" << statistics.tetgenWithoutQualityBound << "\n"
           << std::setw(24) << "tetgen remeshed" << statistics.tetgenRemeshed << "\n"
           << std::setw(24) << "input remeshed boxes" << statistics.inputRemeshedBoxes << " ("
           << statistics.inputDroppedPoints << " points dropped, " << statistics.inputRemeshFailures
           << " failed)\n"
           << std::setw(24) << "sweep remeshed boxes" << statistics.sweepRemeshedBoxes << " ("
           << statistics.sweepDroppedPoints << " points dropped, " << statistics.sweepRemeshFailures
           << " failed)\n"
           << std::setw(24) << "delaunay fallbacks" << statistics.delaunayFallbacks
           << (statistics.fallbackPartitions.empty()
                  ? std::string()
                  : " (partitions " + joinValues(statistics.fallbackPartitions, " ") + ")")
           << "\n";
  }
  else if (statistics.inputRemeshedBoxes > 0 || statistics.inputRemeshFailures > 0)
  {
    // A sliver-laden input meshed anew before the templates (InputImprovement.h).
    stream << std::setw(24) << "input remeshed boxes" << statistics.inputRemeshedBoxes << " ("
           << statistics.inputRemeshFailures << " failed)\n";
  }
  printImprovement(statistics, stream);
  printWarningCounts(statistics, stream);
  printQualitySummaries(statistics, stream);
  stream << "\n"
         << std::setw(24) << "compression" << statistics.compression << "\n"
         << "\n"
         << std::setw(24) << "phase"
         << "seconds\n";
  for (const auto& phase : statistics.seconds)
  {
    stream << std::setw(24) << phase.first << std::fixed << std::setprecision(4) << phase.second
           << std::defaultfloat << "\n";
  }
  stream << std::right;
}

Status writeStatisticsJson(const RefineStatistics& statistics, const std::string& fileName)
{
  std::ofstream file(fileName);
  if (!file)
    return Status::failure("cannot write statistics file '" + fileName + "'");
  file << std::setprecision(17);
  file << "{\n"
       << "  \"input\": {\"file\": " << jsonString(statistics.inputFile)
       << ", \"points\": " << statistics.inputPoints << ", \"cells\": " << statistics.inputCells
       << "},\n"
       << "  \"output\": {\"file\": " << jsonString(statistics.outputFile)
       << ", \"points\": " << statistics.outputPoints << ", \"cells\": " << statistics.outputCells
       << "},\n"
       << "  \"colors\": " << statistics.numberOfColors << ",\n"
       << "  \"partitions\": " << statistics.numberOfPartitions << ",\n"
       << "  \"partitioner\": " << jsonString(statistics.partitioner) << ",\n"
       << "  \"materialLabelArrays\": " << jsonString(statistics.materialLabelArrays) << ",\n"
       << "  \"interfacePoints\": " << statistics.interfacePoints << ",\n"
       << "  \"partitionByRegion\": " << (statistics.partitionByRegion ? "true" : "false") << ",\n"
       << "  \"partitionsPerRegion\": " << statistics.partitionsPerRegion << ",\n"
       << "  \"coloring\": " << jsonString(statistics.coloring) << ",\n"
       << "  \"partitionsPerColor\": [" << joinValues(statistics.partitionsPerColor, ", ") << "],\n"
       << "  \"cellsPerColor\": [" << joinValues(statistics.cellsPerColor, ", ") << "],\n"
       << "  \"colorBalance\": " << statistics.colorBalance << ",\n"
       << "  \"threads\": " << statistics.numberOfThreads << ",\n"
       << "  \"iterations\": " << statistics.numberOfIterations << ",\n"
       << "  \"iterationsRun\": " << statistics.iterationsRun << ",\n"
       << "  \"refinementConverged\": " << (statistics.refinementConverged ? "true" : "false")
       << ",\n";
  if (!statistics.sizeArray.empty())
  {
    file << "  \"sizeField\": {\"array\": " << jsonString(statistics.sizeArray)
         << ", \"gradation\": " << statistics.sizeGradation
         << ", \"edgesWithinBounds\": " << statistics.edgesWithinSizeBounds
         << ", \"edgeSizeRatioHistogram\": [" << joinValues(statistics.edgeSizeRatioHistogram, ", ")
         << "]},\n";
  }
  file << "  \"method\": " << jsonString(statistics.method) << ",\n"
       << "  \"edgeLengthThreshold\": " << statistics.edgeLengthThreshold << ",\n"
       << "  \"volumeBound\": " << statistics.volumeBound << ",\n"
       << "  \"tetgenPoints\": " << statistics.tetgenPoints << ",\n"
       << "  \"tetgenRetries\": " << statistics.tetgenRetries << ",\n"
       << "  \"tetgenWithoutQualityBound\": " << statistics.tetgenWithoutQualityBound << ",\n"
       << "  \"tetgenRemeshed\": " << statistics.tetgenRemeshed << ",\n"
       << "  \"sweepRemeshedBoxes\": " << statistics.sweepRemeshedBoxes << ",\n"
       << "  \"sweepDroppedPoints\": " << statistics.sweepDroppedPoints << ",\n"
       << "  \"sweepRemeshFailures\": " << statistics.sweepRemeshFailures << ",\n"
       << "  \"inputRemeshedBoxes\": " << statistics.inputRemeshedBoxes << ",\n"
       << "  \"inputDroppedPoints\": " << statistics.inputDroppedPoints << ",\n"
       << "  \"inputRemeshFailures\": " << statistics.inputRemeshFailures << ",\n"
       << "  \"delaunayFallbacks\": " << statistics.delaunayFallbacks << ",\n"
       << "  \"fallbackPartitions\": [" << joinValues(statistics.fallbackPartitions, ", ") << "],\n"
       << "  \"compression\": " << jsonString(statistics.compression) << ",\n";
  writeImprovementJson(statistics, file);
  file << "  \"colorOfPartition\": [" << joinValues(statistics.colorOfPartition, ", ") << "],\n"
       << "  \"partitionTaskSeconds\": [";
  for (size_t index = 0; index < statistics.partitionTaskSeconds.size(); ++index)
  {
    file << (index ? ", " : "") << statistics.partitionTaskSeconds[index];
  }
  file << "],\n";
  file << "  \"warnings\": [";
  for (size_t index = 0; index < statistics.warnings.size(); ++index)
  {
    const AdaptationWarning& warning = statistics.warnings[index];
    file << (index ? ",\n    " : "\n    ")
         << "{\"kind\": " << jsonString(warningKindName(warning.kind))
         << ", \"partition\": " << warning.partition << ", \"text\": " << jsonString(warning.text)
         << "}";
  }
  file << (statistics.warnings.empty() ? "],\n" : "\n  ],\n");
  file << "  \"seconds\": {";
  for (size_t index = 0; index < statistics.seconds.size(); ++index)
  {
    file << (index ? ", " : "") << jsonString(statistics.seconds[index].first) << ": "
         << statistics.seconds[index].second;
  }
  file << "}\n}\n";
  file.close();
  if (!file)
    return Status::failure("cannot write statistics file '" + fileName + "'");
  return Status::success();
}

} // namespace cgmesh
