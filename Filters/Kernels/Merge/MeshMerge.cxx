#include "Merge/MeshMerge.h"

#include "Core/TetLocator.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <new>
#include <utility>

namespace cgmesh
{
namespace
{

// Points whose recorded location no longer holds (moved, or derived from a moved point) get
// barycentric weights in the input tet that contains their final position.
class Relocator
{
public:
  Relocator(PointId totalPoints, const RelocationInput& relocation)
    : Input(relocation.input)
  {
    if (!this->Input || !relocation.movedPoints || relocation.movedPoints->empty())
    {
      return;
    }
    this->Flags.assign(totalPoints, 0);
    for (PointId p : *relocation.movedPoints)
    {
      this->Flags[p] = 1;
    }
    const TetMesh* input = this->Input;
    this->Locator =
      std::make_unique<TetLocator>(input->tets, [input](PointId id) { return input->point(id); });
  }

  bool isMoved(PointId p) const { return !this->Flags.empty() && this->Flags[p]; }

  // A new point inherits relocation from any point it is made of, but not from a source in name
  // only: a point TetGen put on a boundary face, with rounding noise as the weight of a moved
  // interior corner, was located anew in the input tet it lies in, whose interior corner then
  // weighed more than the negligible, and the point lost the labels its face's corners share (3
  // of the 20,215 hull points of TetGen's tetrahedralisation of 4,000 random points).
  bool inheritsMove(PointId p, const PointSource& location)
  {
    for (int slot = 0; slot < 4 && !this->Flags.empty() && !this->Flags[p]; ++slot)
    {
      this->Flags[p] = std::abs(location.weights[slot]) > NegligibleSourceWeight &&
        this->Flags[location.points[slot]];
    }
    return this->isMoved(p);
  }

  void appendLocation(const double* point, PointProvenance& all) const
  {
    const auto where = this->Locator->locate(point);
    for (int k = 0; k < 4; ++k)
    {
      all.sources.push_back(this->Input->tets[where.tet][k]);
      all.weights.push_back(where.barycentric[k]);
    }
    all.offsets.push_back(static_cast<std::int64_t>(all.sources.size()));
  }

private:
  const TetMesh* Input;
  std::vector<char> Flags;
  std::unique_ptr<TetLocator> Locator;
};

// The weighted sum of the parents' expansions, equal sources merged.
void appendExpansion(
  const PointSource& location, PointProvenance& all, std::vector<std::pair<PointId, double>>& terms)
{
  terms.clear();
  for (int slot = 0; slot < 4; ++slot)
  {
    if (location.weights[slot] == 0)
    {
      continue;
    }
    const PointId parent = location.points[slot];
    for (std::int64_t k = all.offsets[parent]; k < all.offsets[parent + 1]; ++k)
    {
      terms.emplace_back(all.sources[k], location.weights[slot] * all.weights[k]);
    }
  }
  std::sort(terms.begin(), terms.end());
  for (std::size_t k = 0; k < terms.size(); ++k)
  {
    if (k + 1 < terms.size() && terms[k + 1].first == terms[k].first)
    {
      terms[k + 1].second += terms[k].second;
      continue;
    }
    all.sources.push_back(terms[k].first);
    all.weights.push_back(terms[k].second);
  }
  all.offsets.push_back(static_cast<std::int64_t>(all.sources.size()));
}

// Weights of every global point over input points. A new point is a weighted sum of points with
// smaller ids (it was inserted after them), so one pass in id order suffices.
PointProvenance expandProvenance(PointId inputPointCount,
  const std::vector<PointSource>& newPointSources, const std::vector<double>& coordinates,
  const RelocationInput& relocation)
{
  const PointId total = inputPointCount + static_cast<PointId>(newPointSources.size());
  Relocator relocator(total, relocation);
  PointProvenance all;
  all.offsets.reserve(total + 1);
  all.offsets.push_back(0);
  for (PointId p = 0; p < inputPointCount; ++p)
  {
    if (relocator.isMoved(p))
    {
      relocator.appendLocation(coordinates.data() + 3 * p, all);
      continue;
    }
    all.sources.push_back(p);
    all.weights.push_back(1.0);
    all.offsets.push_back(static_cast<std::int64_t>(all.sources.size()));
  }
  std::vector<std::pair<PointId, double>> terms;
  for (std::size_t index = 0; index < newPointSources.size(); ++index)
  {
    const PointId point = inputPointCount + static_cast<PointId>(index);
    if (relocator.inheritsMove(point, newPointSources[index]))
    {
      relocator.appendLocation(coordinates.data() + 3 * point, all);
      continue;
    }
    appendExpansion(newPointSources[index], all, terms);
  }
  return all;
}

// The provenance of the points some tet uses (outputIdOf >= 0), in output order.
void keepProvenanceOfUsedPoints(const PointProvenance& all, const std::vector<PointId>& outputIdOf,
  PointId inputPointCount, PointProvenance& kept)
{
  kept.offsets.push_back(0);
  for (std::size_t p = 0; p < outputIdOf.size(); ++p)
  {
    if (outputIdOf[p] < 0)
    {
      continue;
    }
    kept.sources.insert(kept.sources.end(), all.sources.begin() + all.offsets[p],
      all.sources.begin() + all.offsets[p + 1]);
    kept.weights.insert(kept.weights.end(), all.weights.begin() + all.offsets[p],
      all.weights.begin() + all.offsets[p + 1]);
    kept.offsets.push_back(static_cast<std::int64_t>(kept.sources.size()));
    kept.inputPoints.push_back(
      static_cast<PointId>(p) < inputPointCount ? static_cast<PointId>(p) : -1);
  }
}

// Points no tet uses are dropped; the others keep their global order. A point on an interface
// is marked by every partition that holds it, so the marks are atomic; counting and numbering
// then run over fixed ranges of points, which makes the numbering independent of the schedule.
Status numberUsedPoints(const std::vector<PartitionMesh>& partitions, PointId globalCount,
  const ParallelFor& parallelFor, std::vector<PointId>& outputIdOf, PointId& outputCount)
{
  std::vector<std::atomic<unsigned char>> used(globalCount);
  Status status = parallelFor(static_cast<std::int64_t>(partitions.size()),
    [&](std::int64_t part)
    {
      for (const Tet& tet : partitions[part].tets)
      {
        for (PointId p : tet)
        {
          used[p].store(1, std::memory_order_relaxed);
        }
      }
    });
  std::vector<PointId> firstOfRange;
  if (status.ok())
  {
    status = offsetsOfAtomicCounts(used, parallelFor, firstOfRange);
  }
  if (!status.ok())
  {
    return status;
  }
  outputCount = firstOfRange.back();
  outputIdOf.resize(globalCount);
  return forEachRange(parallelFor, globalCount, IndicesPerCopyRange,
    [&](std::int64_t begin, std::int64_t end)
    {
      PointId next = firstOfRange[begin / IndicesPerCopyRange];
      for (std::int64_t p = begin; p < end; ++p)
      {
        outputIdOf[p] = used[p].load(std::memory_order_relaxed) ? next++ : -1;
      }
    });
}

// The used points' coordinates (and sizes) at their output ids. When every point is used the ids
// are the global ones and the arrays are taken as they are: copying the Big cube's 1 M points
// cost 16 ms at one thread and at two, most of it zero-filling the copy before writing it.
Status moveUsedPoints(std::vector<double>& coordinates, std::vector<double>& pointSizes,
  const std::vector<PointId>& outputIdOf, PointId outputCount, const ParallelFor& parallelFor,
  TetMesh& mesh)
{
  if (outputCount == static_cast<PointId>(outputIdOf.size()))
  {
    mesh.coordinates = std::move(coordinates);
    mesh.sizes = std::move(pointSizes);
    return Status::success();
  }
  const bool withSizes = !pointSizes.empty();
  mesh.coordinates.resize(3 * outputCount);
  if (withSizes)
  {
    mesh.sizes.resize(outputCount);
  }
  return forEachRange(parallelFor, static_cast<std::int64_t>(outputIdOf.size()),
    IndicesPerCopyRange,
    [&](std::int64_t begin, std::int64_t end)
    {
      for (std::int64_t p = begin; p < end; ++p)
      {
        const PointId to = outputIdOf[p];
        if (to < 0)
        {
          continue;
        }
        std::copy(coordinates.begin() + 3 * p, coordinates.begin() + 3 * p + 3,
          mesh.coordinates.begin() + 3 * to);
        if (withSizes)
        {
          mesh.sizes[to] = pointSizes[p];
        }
      }
    });
}

// Every partition's tets, renumbered, in partition order. Sized once and filled partition by
// partition into disjoint ranges: growing three vectors tet by tet cost 0.39 s of the 0.44 s
// merge of a 6 M-tet output, all of it on one thread.
Status copyTets(const std::vector<PartitionMesh>& partitions,
  const std::vector<PointId>& outputIdOf, MergedMesh& merged, const ParallelFor& parallelFor)
{
  std::vector<std::size_t> first(partitions.size() + 1, 0);
  for (std::size_t part = 0; part < partitions.size(); ++part)
  {
    first[part + 1] = first[part] + partitions[part].tets.size();
  }
  const bool hasRegions = std::any_of(partitions.begin(), partitions.end(),
    [](const PartitionMesh& partition) { return !partition.regions.empty(); });
  merged.mesh.tets.resize(first.back());
  merged.parentCell.resize(first.back());
  if (hasRegions)
  {
    merged.mesh.regions.resize(first.back());
  }
  return parallelFor(static_cast<std::int64_t>(partitions.size()),
    [&](std::int64_t part)
    {
      const PartitionMesh& partition = partitions[part];
      for (std::size_t t = 0; t < partition.tets.size(); ++t)
      {
        const Tet& tet = partition.tets[t];
        const std::size_t at = first[part] + t;
        merged.mesh.tets[at] = { outputIdOf[tet[0]], outputIdOf[tet[1]], outputIdOf[tet[2]],
          outputIdOf[tet[3]] };
        merged.parentCell[at] = partition.parentCells[t];
        if (hasRegions)
        {
          merged.mesh.regions[at] = partition.regions[t];
        }
      }
    });
}

} // namespace

Status mergePartitions(const std::vector<PartitionMesh>& partitions,
  std::vector<double> coordinates, PointId inputPointCount,
  const std::vector<PointSource>& newPointSources, MergedMesh& merged,
  const RelocationInput& relocation, bool withProvenance, std::vector<double> pointSizes,
  const ParallelFor& parallelFor)
{
  try
  {
    const PointId globalCount = static_cast<PointId>(coordinates.size() / 3);
    std::vector<PointId> outputIdOf;
    PointId outputCount = 0;
    merged = MergedMesh();
    Status status = numberUsedPoints(partitions, globalCount, parallelFor, outputIdOf, outputCount);
    if (!status.ok())
    {
      return status;
    }
    merged.removedPoints = globalCount - outputCount;
    // The provenance reads the coordinates before they are moved.
    if (withProvenance)
    {
      keepProvenanceOfUsedPoints(
        expandProvenance(inputPointCount, newPointSources, coordinates, relocation), outputIdOf,
        inputPointCount, merged.provenance);
    }
    status =
      moveUsedPoints(coordinates, pointSizes, outputIdOf, outputCount, parallelFor, merged.mesh);
    if (!status.ok())
    {
      return status;
    }
    return copyTets(partitions, outputIdOf, merged, parallelFor);
  }
  catch (const std::bad_alloc&)
  {
    return Status::failure(ErrorKind::OutOfMemory, "out of memory while merging partitions");
  }
}

} // namespace cgmesh
