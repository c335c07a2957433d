#include "AdaptationPlan.h"

#include "Coloring/PartitionColoring.h"
#include "Core/Geometry.h"
#include "ParallelFor.h"
#include "Refinement/SizeField.h"
#include "Refinement/TetGenRefiner.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace cgmesh
{
namespace
{

constexpr int AutomaticTemplatePartitions = 1024;
constexpr double DelaunayTetsPerPartition = 30000;
constexpr int MinimumAutomaticPartitions = 8;
constexpr int MaximumAutomaticPartitions = 1024;

Status invalidOption(std::string message)
{
  return Status::failure(ErrorKind::InvalidOption, std::move(message));
}

// Comma-separated numbers; false on anything else (an empty text gives no numbers).
bool parseNumbers(const std::string& text, std::vector<double>& numbers)
{
  numbers.clear();
  std::size_t position = 0;
  while (position < text.size())
  {
    const std::size_t comma = text.find(',', position);
    const std::string item =
      text.substr(position, comma == std::string::npos ? std::string::npos : comma - position);
    char* end = nullptr;
    const double value = std::strtod(item.c_str(), &end);
    if (item.empty() || end == item.c_str() ||
      std::string(end).find_first_not_of(' ') != std::string::npos || !std::isfinite(value))
    {
      return false;
    }
    numbers.push_back(value);
    if (comma == std::string::npos)
    {
      break;
    }
    position = comma + 1;
    if (position == text.size())
    {
      return false; // a trailing comma
    }
  }
  return true;
}

Status parseSelection(const AdaptationOptions& options, AdaptationPlan& plan)
{
  std::vector<double> numbers;
  if (!parseNumbers(options.refinementRegions, numbers))
  {
    return invalidOption("RefinementRegions '" + options.refinementRegions +
      "' is not a comma-separated list of region ids");
  }
  for (double value : numbers)
  {
    if (value != std::round(value) || std::abs(value) > INT_MAX)
    {
      return invalidOption("RefinementRegions '" + options.refinementRegions +
        "' holds a value that is not an integer region id");
    }
    plan.refinementRegions.push_back(static_cast<int>(value));
  }
  if (!parseNumbers(options.refinementBox, numbers) || (numbers.size() != 6 && !numbers.empty()))
  {
    return invalidOption("RefinementBox '" + options.refinementBox +
      "' is not six comma-separated numbers x0,y0,z0,x1,y1,z1");
  }
  if (numbers.size() == 6)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      if (numbers[axis] > numbers[axis + 3])
      {
        return invalidOption(
          "RefinementBox '" + options.refinementBox + "' has a lower corner above its upper one");
      }
    }
    plan.hasRefinementBox = true;
    std::copy(numbers.begin(), numbers.end(), plan.refinementBox.begin());
  }
  return Status::success();
}

// Every region RefinementRegions lists must be one of the input's: a typo would otherwise select
// nothing and pass silently, as an unknown array name would.
Status checkSelectedRegionsExist(const AdaptationOptions& options, const TetMesh& input)
{
  AdaptationPlan selection;
  if (!parseSelection(options, selection).ok() || !input.hasRegions())
  {
    return Status::success(); // reported by checkOptions()
  }
  for (int region : selection.refinementRegions)
  {
    if (std::find(input.regions.begin(), input.regions.end(), region) != input.regions.end())
    {
      continue;
    }
    std::vector<int> present = input.regions;
    std::sort(present.begin(), present.end());
    present.erase(std::unique(present.begin(), present.end()), present.end());
    std::string listed;
    constexpr std::size_t Shown = 20;
    for (std::size_t k = 0; k < std::min(present.size(), Shown); ++k)
    {
      listed += (k > 0 ? ", " : "") + std::to_string(present[k]);
    }
    if (present.size() > Shown)
    {
      listed += ", ... (" + std::to_string(present.size()) + " in all)";
    }
    return invalidOption("RefinementRegions lists region " + std::to_string(region) +
      ", which no tet has; the region array's values are " + listed);
  }
  return Status::success();
}

Status checkOptions(const AdaptationOptions& options, bool hasRegions, bool hasSizes, bool empty)
{
  AdaptationPlan selection;
  const Status parsed = parseSelection(options, selection);
  if (!parsed.ok())
  {
    return parsed;
  }
  if (!selection.refinementRegions.empty() && !hasRegions && !empty)
  {
    return invalidOption("RefinementRegions needs a region array (RegionArrayName)");
  }
  if (selection.restricted() && options.method == RefinementMethod::Delaunay)
  {
    return invalidOption("RefinementRegions and RefinementBox work with the Template method only");
  }
  if (options.numberOfIterations < 0)
  {
    return invalidOption("the number of iterations must not be negative");
  }
  if (!options.partitionByRegion && options.numberOfPartitions < 0)
  {
    return invalidOption("the number of partitions must be at least 0 (0: automatic)");
  }
  if (options.partitionByRegion && !hasRegions && !empty)
  {
    return invalidOption("partitioning by region needs a region array");
  }
  if (options.partitionByRegion && options.partitionsPerRegion < 1)
  {
    return invalidOption("the number of partitions per region must be at least 1");
  }
  if (!makeColoring(options.coloring))
  {
    return invalidOption("unknown colouring '" + options.coloring + "'");
  }
  if (options.method == RefinementMethod::Template && !hasSizes &&
    !(options.maximumEdgeLength > 0) && !(options.edgeLengthFactor > 0))
  {
    return invalidOption("set a positive maximum edge length or edge length factor");
  }
  if (hasSizes && !(options.sizeGradation >= 1.0))
  {
    return invalidOption("the size gradation must be at least 1");
  }
  if (options.method == RefinementMethod::Delaunay)
  {
    if (!hasSizes && !(options.maximumVolume > 0) && !(options.volumeFactor > 0))
    {
      return invalidOption("set a positive maximum volume or volume factor");
    }
    if (!(options.radiusEdgeRatio >= 1.0))
    {
      return invalidOption("the radius-edge ratio bound must be at least 1");
    }
  }
  return Status::success();
}

// What partitionByRegion() will make: each region min(partitionsPerRegion, its tets) parts. A
// region with fewer tets than asked for is named in a warning, as a reduced NumberOfPartitions is.
int partitionsByRegion(
  const TetMesh& input, int partitionsPerRegion, std::vector<AdaptationWarning>& warnings)
{
  std::vector<int> regions = input.regions;
  std::sort(regions.begin(), regions.end());
  std::int64_t total = 0;
  int reducedRegions = 0;
  std::string firstReduced;
  for (auto first = regions.begin(); first != regions.end();)
  {
    const auto last = std::upper_bound(first, regions.end(), *first);
    if (last - first < partitionsPerRegion && reducedRegions++ == 0)
    {
      firstReduced =
        "region " + std::to_string(*first) + " has " + std::to_string(last - first) + " tetrahedra";
    }
    total += std::min<std::int64_t>(partitionsPerRegion, last - first);
    first = last;
  }
  if (reducedRegions > 0)
  {
    warnings.push_back({ WarningKind::PartitionsReduced, -1,
      "requested " + std::to_string(partitionsPerRegion) + " partitions per region, but " +
        std::to_string(reducedRegions) + (reducedRegions == 1 ? " region has" : " regions have") +
        " fewer tetrahedra (" + firstReduced + "), cut into one partition per tetrahedron; " +
        "using " + std::to_string(total) + " partitions in all" });
  }
  return static_cast<int>(total);
}

// What Delaunay refinement makes of the input: under the volume bound, from the input's mean tet
// volume, or with a size field (then `volumeBound` is 0) tet by tet at the mean size of its
// corners.
double forecastDelaunayOutput(const TetMesh& input, double meanVolume, double volumeBound)
{
  if (!input.hasSizes())
  {
    return forecastDelaunayTets(
      meanVolume * static_cast<double>(input.numberOfTets()), volumeBound);
  }
  return forecastDelaunayTetsForSizes(input.tets, input.coordinates, input.sizes);
}

// NumberOfPartitions 0. Templates: 1024, plenty of colour-sized work for many cores. Delaunay:
// one partition per about 30,000 forecast output tets, between 8 and 1024. Each partition's
// interface is split by templates before TetGen and TetGen refines towards it, so many small
// partitions make more tets and more TetGen calls; on the Kuhn cube N=25 at V = 0.1 x the mean
// volume, 64 partitions gave 1.88 M tets in 18.5 s on one thread against 2.21 M in 32 s with
// 1024. A small input pays most: the benchmark's poor input (121,000 tets from serial TetGen)
// got 149,310 tets with 64 partitions and 130,481 with 8, in the same 0.77 s at 2 threads; such
// a run is short at any parallel width. The count never depends on the thread count, so neither
// does the output.
int automaticPartitions(const AdaptationOptions& options, double delaunayForecast)
{
  if (options.method != RefinementMethod::Delaunay)
  {
    return AutomaticTemplatePartitions;
  }
  const double partitions = delaunayForecast / DelaunayTetsPerPartition;
  return static_cast<int>(std::lround(std::min<double>(
    MaximumAutomaticPartitions, std::max<double>(MinimumAutomaticPartitions, partitions))));
}

// Whether a run may be refined in the whole-input call, its forecast aside (below).
bool mayRefineInWholeInputCall(const AdaptationOptions& options, const AdaptationPlan& plan)
{
  return options.method == RefinementMethod::Delaunay && plan.volumeBound > 0 && !plan.sizeField &&
    !plan.restricted();
}

// Whether meshing a sliver-laden input anew as a whole (InputImprovement.h) also refines it to
// the volume bound: for Delaunay runs whose forecast output fits the fewest automatic partitions.
// That call already costs about what serial TetGen's refinement does, and the partitions that
// would refine its tets again, split at their interfaces, take more: the benchmark's poor input
// (26,269 tets, V = 2e-4) took 1.6 s at one thread and 1.33 at two for 130,469 tets, with 8
// partitions in 6 colours, against 0.77 s of serial TetGen for 121,131; refined in the one call,
// 1.40 and 1.12 s for 119,232 tets against 0.94 s (docs/design.md, section 5). Larger outputs
// keep the partitions, which the threads share.
bool refinesInWholeInputCall(
  const AdaptationOptions& options, const AdaptationPlan& plan, double delaunayForecast)
{
  return mayRefineInWholeInputCall(options, plan) &&
    delaunayForecast <= MinimumAutomaticPartitions * DelaunayTetsPerPartition;
}

// `delaunayForecast`: forecastDelaunayOutput() for an automatic Delaunay count, else unread.
int resolvePartitions(const TetMesh& input, const AdaptationOptions& options,
  double delaunayForecast, std::vector<AdaptationWarning>& warnings)
{
  const CellId tets = input.numberOfTets();
  if (tets == 0)
  {
    return 1;
  }
  if (options.partitionByRegion)
  {
    return partitionsByRegion(input, options.partitionsPerRegion, warnings);
  }
  if (options.numberOfPartitions == 0)
  {
    // Automatic: never more partitions than tets, and no warning, as nothing was asked.
    return static_cast<int>(std::min<CellId>(tets, automaticPartitions(options, delaunayForecast)));
  }
  if (options.numberOfPartitions > tets)
  {
    warnings.push_back({ WarningKind::PartitionsReduced, -1,
      "requested " + std::to_string(options.numberOfPartitions) + " partitions for " +
        std::to_string(tets) + " tetrahedra; using " + std::to_string(tets) });
    return static_cast<int>(tets);
  }
  return options.numberOfPartitions;
}

// Automatic: Hilbert runs for templates, METIS in curve chunks for Delaunay. Measured at 2
// threads (FinFET of 843,973 tets): templates (factor 0.5) 13.7 s with METIS, 3.5 s of it
// partitioning, against 10.7 s with Hilbert at the same quality; Delaunay (V = mean volume) on
// the Kuhn cube N=25 makes 10% more tets with Hilbert's longer interfaces (each is pre-split to
// the V-tet's edge) and improves them 2 s longer, which outweighs the 0.3 s of METIS.
PartitionerKind resolvePartitioner(const AdaptationOptions& options)
{
  if (options.partitionByRegion)
  {
    return PartitionerKind::Metis;
  }
  if (options.partitioner != PartitionerKind::Automatic)
  {
    return options.partitioner;
  }
  return options.method == RefinementMethod::Template ? PartitionerKind::Hilbert
                                                      : PartitionerKind::CurveChunks;
}

} // namespace

namespace
{

// The sum of perTet(t) over all tets: ranges summed concurrently, then added in range order, so
// the sum is the same for any thread count.
template <typename PerTet>
double sumOverTets(const TetMesh& mesh, int threads, PerTet&& perTet)
{
  const std::int64_t rangeSize = IndicesPerCopyRange;
  std::vector<double> sumOfRange((mesh.numberOfTets() + rangeSize - 1) / rangeSize, 0.0);
  const Status status = forEachRange(parallelForOn(threads), mesh.numberOfTets(), rangeSize,
    [&](std::int64_t begin, std::int64_t end)
    {
      double sum = 0;
      for (CellId t = begin; t < end; ++t)
      {
        sum += perTet(mesh.tets[t]);
      }
      sumOfRange[begin / rangeSize] = sum;
    });
  if (!status.ok())
  {
    throw std::runtime_error(status.message());
  }
  double sum = 0;
  for (double rangeSum : sumOfRange)
  {
    sum += rangeSum;
  }
  return sum;
}

} // namespace

// Mean over the six edges of every tet (shared edges count once per tet, which weighs edges by
// how many tets use them and needs no edge list).
double meanTetEdgeLength(const TetMesh& mesh, int threads)
{
  const double sum = sumOverTets(mesh, threads,
    [&](const Tet& tet)
    {
      double length = 0;
      for (const auto& edge : TetEdgeCorners)
      {
        length += std::sqrt(squaredEdgeLength(mesh, tet[edge[0]], tet[edge[1]]));
      }
      return length;
    });
  return mesh.tets.empty() ? 0 : sum / (6.0 * static_cast<double>(mesh.tets.size()));
}

double meanTetVolume(const TetMesh& mesh, int threads)
{
  const double sum = sumOverTets(
    mesh, threads, [&](const Tet& tet) { return std::abs(signedVolume6(mesh, tet)) / 6.0; });
  return mesh.tets.empty() ? 0 : sum / static_cast<double>(mesh.tets.size());
}

Status checkOptionsAndInput(const TetMesh& input, const AdaptationOptions& options)
{
  if (input.coordinates.size() % 3 != 0)
  {
    return Status::failure(
      ErrorKind::InvalidInput, "point coordinates are not a multiple of three values");
  }
  if (input.hasRegions() && input.regions.size() != input.tets.size())
  {
    return Status::failure(
      ErrorKind::InvalidInput, "the region array does not have one value per tet");
  }
  const PointId pointCount = input.numberOfPoints();
  for (const Tet& tet : input.tets)
  {
    for (PointId p : tet)
    {
      if (p < 0 || p >= pointCount)
      {
        return Status::failure(ErrorKind::InvalidInput,
          "a tet references point " + std::to_string(p) + " but the mesh has " +
            std::to_string(pointCount) + " points");
      }
    }
  }
  if (input.hasSizes())
  {
    const Status sizes = checkSizeField(input);
    if (!sizes.ok())
    {
      return sizes;
    }
  }
  const Status checked =
    checkOptions(options, input.hasRegions(), input.hasSizes(), input.tets.empty());
  return checked.ok() ? checkSelectedRegionsExist(options, input) : checked;
}

AdaptationPlan resolvePlan(
  const TetMesh& input, const AdaptationOptions& options, std::vector<AdaptationWarning>& warnings)
{
  AdaptationPlan plan;
  plan.threads = resolveThreadCount(options.numberOfThreads);
  double meanVolume = 0; // Delaunay under a volume bound: the input's, read once
  if (input.hasSizes())
  {
    // Edges are measured against the field, and TetGen gets it per point: no single threshold
    // or volume bound.
    plan.sizeField = true;
  }
  else if (options.method == RefinementMethod::Delaunay)
  {
    meanVolume = meanTetVolume(input, plan.threads);
    plan.volumeBound =
      options.maximumVolume > 0 ? options.maximumVolume : options.volumeFactor * meanVolume;
    plan.edgeLengthThreshold = interfaceEdgeLengthForVolume(plan.volumeBound);
    // Improvement must not undo Delaunay refinement's volume bound.
    plan.improvementVolumeBound = plan.volumeBound;
  }
  else
  {
    plan.edgeLengthThreshold = options.maximumEdgeLength > 0
      ? options.maximumEdgeLength
      : options.edgeLengthFactor * meanTetEdgeLength(input, plan.threads);
  }
  parseSelection(options, plan); // checked in checkOptionsAndInput
  // The Delaunay forecast, made once for the automatic partition count and the whole-input rule
  // (a pass over every tet), and only when one of them reads it.
  const bool automaticCount = options.numberOfPartitions == 0 && !options.partitionByRegion;
  const double delaunayForecast = options.method == RefinementMethod::Delaunay &&
      !input.tets.empty() && (automaticCount || mayRefineInWholeInputCall(options, plan))
    ? forecastDelaunayOutput(input, meanVolume, plan.volumeBound)
    : 0;
  plan.partitions = resolvePartitions(input, options, delaunayForecast, warnings);
  plan.partitioner = resolvePartitioner(options);
  plan.wholeInputCallRefines = refinesInWholeInputCall(options, plan, delaunayForecast);
  // About as many boxes as refinement partitions, so that a box is about a partition's size.
  plan.boxesPerAxis =
    std::max(1, static_cast<int>(std::lround(std::cbrt(std::max(1, plan.partitions)))));
  return plan;
}

} // namespace cgmesh
