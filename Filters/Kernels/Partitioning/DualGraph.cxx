#include "Partitioning/DualGraph.h"

#include "Core/DefaultInitAllocator.h"
#include "Core/FaceKey.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <tuple>

namespace cgmesh
{

Status buildDualGraph(const TetList& tets, DualGraph& graph, const ParallelFor& parallelFor)
{
  // A face is matched with its twin after sorting by corners. Sorting all 4n faces at once would
  // cost a global sort; instead they are scattered into buckets of smallest-corner ids (each
  // range of tets writes its own slice of every bucket, so the scatter needs no atomics and its
  // order is the mesh's), and each bucket is sorted alone, in cache.
  struct FaceOfTet
  {
    PointId first, second, third; // corners, ascending
    CellId face;                  // 4 * tet + the corner the face leaves out
    bool operator<(const FaceOfTet& other) const
    {
      return std::tie(first, second, third, face) <
        std::tie(other.first, other.second, other.third, other.face);
    }
  };
  const CellId tetCount = static_cast<CellId>(tets.size());
  const std::int64_t rangeSize = IndicesPerCopyRange;
  const std::int64_t ranges = (tetCount + rangeSize - 1) / rangeSize;
  std::vector<PointId> highestOfRange(static_cast<std::size_t>(ranges), -1);
  Status status = forEachRange(parallelFor, tetCount, rangeSize,
    [&](std::int64_t begin, std::int64_t end)
    {
      PointId highest = -1;
      for (CellId t = begin; t < end; ++t)
      {
        highest = std::max(highest, *std::max_element(tets[t].begin(), tets[t].end()));
      }
      highestOfRange[begin / rangeSize] = highest;
    });
  const PointId pointCount =
    ranges == 0 ? 0 : *std::max_element(highestOfRange.begin(), highestOfRange.end()) + 1;
  // About 16k faces a bucket, at most 4096 buckets (the slice table has ranges x buckets entries).
  const std::int64_t buckets = std::clamp<std::int64_t>(4 * tetCount / 16384, 1, 4096);
  auto bucketOf = [&](PointId point)
  {
    return point * buckets / pointCount;
  };

  // slice[r * buckets + b]: where range r writes its faces of bucket b (first their count).
  std::vector<std::int64_t> slice(static_cast<std::size_t>(ranges * buckets), 0);
  if (status.ok())
  {
    status = forEachRange(parallelFor, tetCount, rangeSize,
      [&](std::int64_t begin, std::int64_t end)
      {
        std::int64_t* count = slice.data() + begin / rangeSize * buckets;
        for (CellId t = begin; t < end; ++t)
        {
          for (int skip = 0; skip < 4; ++skip)
          {
            ++count[bucketOf(sortedFace(tets[t].data(), skip)[0])];
          }
        }
      });
  }
  std::vector<std::int64_t> bucketStart(static_cast<std::size_t>(buckets) + 1, 0);
  {
    std::int64_t next = 0;
    for (std::int64_t b = 0; b < buckets; ++b)
    {
      bucketStart[b] = next;
      for (std::int64_t r = 0; r < ranges; ++r)
      {
        const std::int64_t count = slice[r * buckets + b];
        slice[r * buckets + b] = next;
        next += count;
      }
    }
    bucketStart[buckets] = next;
  }
  std::vector<FaceOfTet, DefaultInitAllocator<FaceOfTet>> faces(4 * tets.size());
  if (status.ok())
  {
    status = forEachRange(parallelFor, tetCount, rangeSize,
      [&](std::int64_t begin, std::int64_t end)
      {
        std::int64_t* next = slice.data() + begin / rangeSize * buckets;
        for (CellId t = begin; t < end; ++t)
        {
          for (int skip = 0; skip < 4; ++skip)
          {
            const auto face = sortedFace(tets[t].data(), skip);
            faces[next[bucketOf(face[0])]++] = { face[0], face[1], face[2], 4 * t + skip };
          }
        }
      });
  }

  // The neighbour across each face, -1 on the boundary: one slot per face, written by the one
  // bucket that holds it. A bucket is sorted by its faces' smallest corner (counting), then each
  // corner's few faces by the other corners and the face id.
  std::vector<CellId> across(4 * tets.size(), -1);
  if (status.ok())
  {
    status = parallelFor(buckets,
      [&](std::int64_t b)
      {
        const PointId low = (b * pointCount + buckets - 1) / buckets;
        const PointId high = ((b + 1) * pointCount + buckets - 1) / buckets;
        const auto first = faces.begin() + bucketStart[b];
        const auto last = faces.begin() + bucketStart[b + 1];
        std::vector<std::int64_t> groupStart(static_cast<std::size_t>(high - low) + 1, 0);
        for (auto face = first; face != last; ++face)
        {
          ++groupStart[face->first - low + 1];
        }
        for (std::size_t g = 1; g < groupStart.size(); ++g)
        {
          groupStart[g] += groupStart[g - 1];
        }
        std::vector<FaceOfTet> grouped(static_cast<std::size_t>(last - first));
        {
          std::vector<std::int64_t> next(groupStart.begin(), groupStart.end() - 1);
          for (auto face = first; face != last; ++face)
          {
            grouped[next[face->first - low]++] = *face;
          }
        }
        for (std::size_t g = 0; g + 1 < groupStart.size(); ++g)
        {
          const auto groupFirst = grouped.begin() + groupStart[g];
          const auto groupLast = grouped.begin() + groupStart[g + 1];
          std::sort(groupFirst, groupLast);
          for (auto face = groupFirst; face != groupLast;)
          {
            auto run = face + 1;
            while (run != groupLast && run->second == face->second && run->third == face->third)
            {
              ++run;
            }
            if (run - face == 2 && face->face / 4 != (face + 1)->face / 4)
            {
              across[face->face] = (face + 1)->face / 4;
              across[(face + 1)->face] = face->face / 4;
            }
            face = run;
          }
        }
      });
  }

  std::vector<std::int64_t> rowOfRange;
  if (status.ok())
  {
    status = offsetsOfRanges(
      parallelFor, tetCount, rangeSize,
      [&](std::int64_t begin, std::int64_t end)
      {
        return static_cast<std::int64_t>(std::count_if(across.begin() + 4 * begin,
          across.begin() + 4 * end, [](CellId tet) { return tet >= 0; }));
      },
      rowOfRange);
  }
  if (!status.ok())
  {
    return status;
  }
  graph.offsets.assign(static_cast<std::size_t>(tetCount) + 1, 0);
  graph.neighbours.resize(static_cast<std::size_t>(rowOfRange.back()));
  return forEachRange(parallelFor, tetCount, rangeSize,
    [&](std::int64_t begin, std::int64_t end)
    {
      std::int64_t row = rowOfRange[begin / rangeSize];
      for (CellId t = begin; t < end; ++t)
      {
        const auto first = graph.neighbours.begin() + row;
        for (int skip = 0; skip < 4; ++skip)
        {
          if (across[4 * t + skip] >= 0)
          {
            graph.neighbours[row++] = across[4 * t + skip];
          }
        }
        std::sort(first, graph.neighbours.begin() + row);
        graph.offsets[t + 1] = row;
      }
    });
}

DualGraph subgraphOfPositions(const DualGraph& graph, const std::vector<CellId>& order,
  const std::vector<CellId>& positionOf, CellId begin, CellId end)
{
  DualGraph sub;
  sub.offsets.reserve(static_cast<std::size_t>(end - begin) + 1);
  sub.neighbours.reserve(4 * static_cast<std::size_t>(end - begin));
  sub.offsets.push_back(0);
  for (CellId position = begin; position < end; ++position)
  {
    const CellId v = order[position];
    for (std::int64_t k = graph.offsets[v]; k < graph.offsets[v + 1]; ++k)
    {
      const CellId at = positionOf[graph.neighbours[k]];
      if (at >= begin && at < end)
      {
        sub.neighbours.push_back(at - begin);
      }
    }
    sub.offsets.push_back(static_cast<std::int64_t>(sub.neighbours.size()));
    if (!graph.vertexWeights.empty())
    {
      sub.vertexWeights.push_back(graph.vertexWeights[v]);
    }
  }
  return sub;
}

DualGraph dualGraphOfPositions(
  const TetList& tets, const std::vector<CellId>& order, CellId begin, CellId end)
{
  const std::size_t count = static_cast<std::size_t>(end - begin);
  std::vector<PointId> corners(4 * count);
  for (std::size_t i = 0; i < count; ++i)
  {
    const Tet& tet = tets[static_cast<std::size_t>(order[begin + static_cast<CellId>(i)])];
    std::copy(tet.begin(), tet.end(), corners.begin() + static_cast<std::ptrdiff_t>(4 * i));
  }
  // At most one neighbour across each of a tet's four faces.
  std::vector<std::array<CellId, 4>> across(count);
  std::vector<std::uint8_t> degree(count, 0);
  forEachDistinctFace(corners.data(), count,
    [&](const std::array<PointId, 3>&, std::size_t first, std::size_t second, std::size_t holders)
    {
      if (holders == 2 && first != second)
      {
        across[first][degree[first]++] = static_cast<CellId>(second);
        across[second][degree[second]++] = static_cast<CellId>(first);
      }
    });
  DualGraph graph;
  graph.offsets.reserve(count + 1);
  graph.neighbours.reserve(4 * count);
  graph.offsets.push_back(0);
  for (std::size_t i = 0; i < count; ++i)
  {
    auto first = across[i].begin();
    auto last = first + degree[i];
    // As buildDualGraph() lists them: by tet id.
    std::sort(first, last, [&](CellId a, CellId b) { return order[begin + a] < order[begin + b]; });
    graph.neighbours.insert(graph.neighbours.end(), first, last);
    graph.offsets.push_back(static_cast<std::int64_t>(graph.neighbours.size()));
  }
  return graph;
}

VertexGroups groupVertices(const std::vector<int>& groupOf, int groups)
{
  VertexGroups grouped;
  grouped.groupStart.assign(static_cast<std::size_t>(groups) + 1, 0);
  for (int group : groupOf)
  {
    ++grouped.groupStart[group + 1];
  }
  for (int g = 0; g < groups; ++g)
  {
    grouped.groupStart[g + 1] += grouped.groupStart[g];
  }
  grouped.order.resize(groupOf.size());
  grouped.positionOf.resize(groupOf.size());
  std::vector<CellId> next(grouped.groupStart.begin(), grouped.groupStart.end() - 1);
  for (std::size_t v = 0; v < groupOf.size(); ++v)
  {
    const CellId position = next[groupOf[v]]++;
    grouped.order[position] = static_cast<CellId>(v);
    grouped.positionOf[v] = position;
  }
  return grouped;
}

} // namespace cgmesh
