#include "RefineReport.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <fstream>
#include <iomanip>
#include <sstream>

namespace cgmesh
{

namespace
{

// JSON key of each phase and the field-data array the filter stores it in.
const std::pair<const char*, const char*> FilterPhases[] = { { "partition", "PartitionSeconds" },
  { "graph", "GraphSeconds" }, { "color", "ColorSeconds" }, { "heal", "HealSeconds" },
  { "adapt", "AdaptSeconds" }, { "post", "PostSeconds" }, { "improve", "ImproveSeconds" },
  { "merge", "MergeSeconds" }, { "quality", "QualitySeconds" }, { "total", "TotalSeconds" } };

double fieldValue(vtkFieldData* fieldData, const char* name)
{
  vtkDataArray* array = fieldData->GetArray(name);
  return (array && array->GetNumberOfTuples() > 0) ? array->GetComponent(0, 0) : 0.0;
}

std::vector<std::int64_t> fieldValues(vtkFieldData* fieldData, const char* name)
{
  std::vector<std::int64_t> values;
  vtkDataArray* array = fieldData->GetArray(name);
  for (vtkIdType tuple = 0; array && tuple < array->GetNumberOfTuples(); ++tuple)
  {
    values.push_back(static_cast<std::int64_t>(array->GetComponent(tuple, 0)));
  }
  return values;
}

std::string fieldString(vtkFieldData* fieldData, const char* name)
{
  auto* array = vtkStringArray::SafeDownCast(fieldData->GetAbstractArray(name));
  return (array && array->GetNumberOfValues() > 0) ? array->GetValue(0) : std::string();
}

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

void collectFilterStatistics(vtkUnstructuredGrid* output, RefineStatistics& statistics)
{
  vtkFieldData* fieldData = output->GetFieldData();
  statistics.outputPoints = output->GetNumberOfPoints();
  statistics.outputCells = output->GetNumberOfCells();
  statistics.numberOfColors = static_cast<int>(fieldValue(fieldData, "NumberOfColors"));
  statistics.numberOfPartitions = static_cast<int>(fieldValue(fieldData, "NumberOfPartitions"));
  statistics.numberOfThreads = static_cast<int>(fieldValue(fieldData, "NumberOfThreads"));
  statistics.edgeLengthThreshold = fieldValue(fieldData, "EdgeLengthThreshold");
  statistics.coloring = fieldString(fieldData, "ColoringAlgorithm");
  statistics.method = fieldString(fieldData, "Method");
  statistics.volumeBound = fieldValue(fieldData, "VolumeBound");
  statistics.delaunayFallbacks =
    static_cast<std::int64_t>(fieldValue(fieldData, "DelaunayFallbacks"));
  statistics.fallbackPartitions = fieldValues(fieldData, "FallbackPartitions");
  statistics.tetgenPoints = static_cast<std::int64_t>(fieldValue(fieldData, "TetGenPoints"));
  statistics.partitionsPerColor = fieldValues(fieldData, "PartitionsPerColor");
  statistics.cellsPerColor = fieldValues(fieldData, "CellsPerColor");
  statistics.colorBalance = fieldValue(fieldData, "ColorBalance");
  for (const auto& phase : FilterPhases)
  {
    statistics.seconds.emplace_back(phase.first, fieldValue(fieldData, phase.second));
  }
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
                : std::string())
         << "\n"
         << std::setw(24) << "coloring" << statistics.coloring << "\n"
         << std::setw(24) << "colors" << statistics.numberOfColors << "\n"
         << std::setw(24) << "partitions per color"
         << joinValues(statistics.partitionsPerColor, " ") << "\n"
         << std::setw(24) << "cells per color" << joinValues(statistics.cellsPerColor, " ") << "\n"
         << std::setw(24) << "color balance" << std::setprecision(4) << statistics.colorBalance
         << "\n"
         << std::setw(24) << "threads" << statistics.numberOfThreads << "\n"
         << std::setw(24) << "iterations" << statistics.numberOfIterations << "\n"
         << std::setw(24) << "method" << statistics.method << "\n"
         << std::setw(24) << "edge length threshold" << std::setprecision(6)
         << statistics.edgeLengthThreshold << "\n";
  if (statistics.method == "delaunay")
  {
    stream << std::setw(24) << "volume bound" << statistics.volumeBound << "\n"
           << std::setw(24) << "tetgen points" << statistics.tetgenPoints << "\n"
           << std::setw(24) << "delaunay fallbacks" << statistics.delaunayFallbacks
           << (statistics.fallbackPartitions.empty()
                  ? std::string()
                  : " (partitions " + joinValues(statistics.fallbackPartitions, " ") + ")")
           << "\n";
  }
  stream << "\n"
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
       << "  \"partitionByRegion\": " << (statistics.partitionByRegion ? "true" : "false") << ",\n"
       << "  \"partitionsPerRegion\": " << statistics.partitionsPerRegion << ",\n"
       << "  \"coloring\": " << jsonString(statistics.coloring) << ",\n"
       << "  \"partitionsPerColor\": [" << joinValues(statistics.partitionsPerColor, ", ") << "],\n"
       << "  \"cellsPerColor\": [" << joinValues(statistics.cellsPerColor, ", ") << "],\n"
       << "  \"colorBalance\": " << statistics.colorBalance << ",\n"
       << "  \"threads\": " << statistics.numberOfThreads << ",\n"
       << "  \"iterations\": " << statistics.numberOfIterations << ",\n"
       << "  \"method\": " << jsonString(statistics.method) << ",\n"
       << "  \"edgeLengthThreshold\": " << statistics.edgeLengthThreshold << ",\n"
       << "  \"volumeBound\": " << statistics.volumeBound << ",\n"
       << "  \"tetgenPoints\": " << statistics.tetgenPoints << ",\n"
       << "  \"delaunayFallbacks\": " << statistics.delaunayFallbacks << ",\n"
       << "  \"fallbackPartitions\": [" << joinValues(statistics.fallbackPartitions, ", ") << "],\n"
       << "  \"seconds\": {";
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
