#include "RefineChecks.h"

#include "AdaptationPlan.h"
#include "Core/Geometry.h"
#include "Core/TetMesh.h"
#include "Refinement/TetGenRefiner.h"
#include "cgmeshTriangleCells.h"
#include "cgmeshVTKConversion.h"

#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace cgmesh
{

namespace
{

// Beyond this many whole splits the bound exceeds any limit (4^40 > 2^53 = the largest one).
constexpr int MaximumCountedSplits = 40;

// The fewest tets a tet becomes when it is split whole (all six edges) in `splits` successive
// passes: 8 children, of which the 4 corner ones are the tet at half size and are split whole
// again; the 4 others count once. g(0) = 1, g(j) = 4 g(j - 1) + 4.
double leastTetsAfterWholeSplits(int splits)
{
  return (7.0 * std::pow(4.0, splits) - 4.0) / 3.0;
}

// Passes, of `iterations`, in which a tet with shortest squared edge `shortest` and its corner
// descendants still have every edge longer than the threshold. The margin keeps it a lower bound
// despite the rounding of midpoints.
int wholeSplits(double shortest, double threshold, int iterations)
{
  int splits = 0;
  const int most = std::min(iterations, MaximumCountedSplits);
  while (splits < most && shortest > threshold * threshold * (1 + 1e-9))
  {
    ++splits;
    shortest /= 4;
  }
  return splits;
}

double shortestSquaredEdge(const TetMesh& mesh, const Tet& tet)
{
  double shortest = squaredEdgeLength(mesh, tet[0], tet[1]);
  for (const auto& edge : TetEdgeCorners)
    shortest = std::min(shortest, squaredEdgeLength(mesh, tet[edge[0]], tet[edge[1]]));
  return shortest;
}

double longestEdge(const TetMesh& mesh)
{
  double longest = 0;
  for (const Tet& tet : mesh.tets)
  {
    for (const auto& edge : TetEdgeCorners)
      longest = std::max(longest, squaredEdgeLength(mesh, tet[edge[0]], tet[edge[1]]));
  }
  return std::sqrt(longest);
}

double largestVolume(const TetMesh& mesh)
{
  double largest = 0;
  for (const Tet& tet : mesh.tets)
    largest = std::max(largest, std::abs(signedVolume6(mesh, tet)) / 6.0);
  return largest;
}

// An exact integer up to 10^15, three digits beyond.
std::string countText(double count)
{
  std::ostringstream text;
  if (count < 1e15)
    text << static_cast<long long>(count);
  else
    text << std::setprecision(3) << count;
  return text.str();
}

// The options for the threshold alone: it does not depend on regions or partitioning.
AdaptationOptions sizingOptions(const AdaptationOptions& options)
{
  AdaptationOptions sizing = options;
  sizing.partitionByRegion = false;
  return sizing;
}

} // namespace

Status checkSizeBeforeRefining(vtkUnstructuredGrid* input, const AdaptationOptions& options)
{
  const double limit = static_cast<double>(options.maximumNumberOfCells);
  const int iterations = options.numberOfIterations;
  // With one iteration the filter's forecast is exact and comes before any large allocation.
  // A size field has no single threshold to bound with, and a selection splits only part of the
  // mesh: the filter's forecast of every pass guards them.
  if (options.method != RefinementMethod::Template || limit <= 0 || iterations < 2 ||
    !options.sizeArrayName.empty() || !options.refinementRegions.empty() ||
    !options.refinementBox.empty())
    return Status::success();
  const double cells = static_cast<double>(input->GetNumberOfCells());
  if (cells * leastTetsAfterWholeSplits(std::min(iterations, MaximumCountedSplits)) <= limit)
    return Status::success(); // not even a whole split of every tet in every pass would exceed it
  const AdaptationOptions sizing = sizingOptions(options);
  TetMesh mesh;
  if (!convertToTetMesh(input, std::string(), mesh).ok() ||
    !checkOptionsAndInput(mesh, sizing).ok())
    return Status::success();
  std::vector<AdaptationWarning> ignored;
  const double threshold = resolvePlan(mesh, sizing, ignored).edgeLengthThreshold;
  double least = 0;
  for (const Tet& tet : mesh.tets)
    least +=
      leastTetsAfterWholeSplits(wholeSplits(shortestSquaredEdge(mesh, tet), threshold, iterations));
  if (least <= limit)
    return Status::success();
  std::ostringstream message;
  message << "refining would produce at least " << countText(least) << " tetrahedra in "
          << iterations << " iterations (edges longer than " << threshold
          << " are split in every pass), more than the limit of " << options.maximumNumberOfCells
          << " (--max-cells); refused before refining: raise the limit or refine less";
  return Status::failure(ErrorKind::SizeLimit, message.str());
}

std::string nothingRefinedWarning(
  vtkUnstructuredGrid* input, const AdaptationOptions& options, const RefineStatistics& statistics)
{
  // Refinement adds points; improvement and the input repairs never do.
  if (statistics.outputPoints > statistics.inputPoints)
    return std::string();
  // The tets alone: tagged triangles are refined with the tets' faces, not by themselves.
  vtkNew<vtkUnstructuredGrid> tets;
  vtkUnstructuredGrid* volume = input;
  if (hasTriangles(input))
  {
    TriangleCells cells;
    separateTriangles(input, tets, cells);
    volume = tets;
  }
  TetMesh mesh;
  if (!convertToTetMesh(volume, std::string(), mesh).ok())
    return std::string();
  std::ostringstream text;
  text << std::setprecision(6) << "nothing was refined: ";
  if (options.method == RefinementMethod::Delaunay)
  {
    if (statistics.tetgenPoints > 0)
      return std::string();
    if (!options.sizeArrayName.empty())
    {
      text << "TetGen inserted no point: no tet's circumradius exceeds " << TetGenRadiusPerSize
           << " times the size field '" << options.sizeArrayName << "' at its corners";
      return text.str();
    }
    text << "TetGen inserted no point under the volume bound " << statistics.volumeBound
         << " and the radius-edge bound " << options.radiusEdgeRatio
         << " (the largest input tet has volume " << largestVolume(mesh) << ")";
    return text.str();
  }
  // With a selection, only edges between two points of selected tets count.
  if (!options.refinementRegions.empty() || !options.refinementBox.empty())
  {
    text << "no edge between two points of the selected tets (";
    if (!options.refinementRegions.empty())
      text << "--refine-regions " << options.refinementRegions
           << (options.refinementBox.empty() ? "" : ", ");
    if (!options.refinementBox.empty())
      text << "--refine-box " << options.refinementBox;
    text << ") is longer than ";
    if (!options.sizeArrayName.empty())
      text << "sqrt(2) times the size field '" << options.sizeArrayName << "' at its midpoint";
    else
      text << "the threshold " << statistics.edgeLengthThreshold;
    return text.str();
  }
  if (!options.sizeArrayName.empty())
  {
    text << "no edge is longer than sqrt(2) times the size field '" << options.sizeArrayName
         << "' at its midpoint";
    return text.str();
  }
  const double longest = longestEdge(mesh);
  const double threshold = statistics.edgeLengthThreshold;
  if (longest > threshold)
    return std::string();
  text << "no edge is longer than the threshold " << threshold;
  if (options.maximumEdgeLength > 0)
    text << " (--max-edge-length)";
  else
    text << " (--edge-length-factor " << options.edgeLengthFactor << " x the mean edge length "
         << threshold / options.edgeLengthFactor << ")";
  text << "; the longest edge is " << longest;
  return text.str();
}

} // namespace cgmesh
