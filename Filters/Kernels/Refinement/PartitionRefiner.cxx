#include "Refinement/PartitionRefiner.h"

#include "Core/Geometry.h"
#include "Core/TetQuality.h"
#include "Refinement/SizeField.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <new>

namespace cgmesh
{
namespace
{

class SplitSession
{
public:
  SplitSession(
    const RefinementContext& context, const PostedSplits& received, PartitionRefinement& refinement)
    : Context(context)
    , Received(received)
    , Refinement(refinement)
  {
  }

  const double* coordinatesOf(PointId id) const
  {
    return pointCoordinates(*this->Context.coordinates, this->Refinement.newCoordinates, id);
  }

  double sizeOf(PointId id) const
  {
    return pointSize(*this->Context.sizes, this->Refinement.newSizes, id);
  }

  bool isLong(PointId a, PointId b) const
  {
    const double* pa = this->coordinatesOf(std::min(a, b));
    const double* pb = this->coordinatesOf(std::max(a, b));
    const double lengthSquared = squaredDistance(pa, pb);
    return this->Context.sizes ? longerThanSize(lengthSquared, this->sizeOf(a), this->sizeOf(b))
                               : lengthSquared > this->Context.squaredThreshold;
  }

  // The midpoint of edge (a, b): the one a neighbour inserted, one made earlier in this
  // partition, or a new one.
  PointId midpointOf(PointId a, PointId b)
  {
    const EdgeKey key = EdgeKey::of(a, b);
    if (const PointId* known = this->Created.find(key))
    {
      return *known;
    }
    // Only an edge between two interface vertices can be shared, so only such an edge can have
    // been split by a neighbour: the others are not looked up among the posted splits.
    const bool shareable = this->mayShare(key.low, key.high);
    PointId vertex;
    if (const PointId* healed = shareable ? this->Received.find(key) : nullptr)
    {
      vertex = *healed;
      this->Refinement.newInterfacePoints.emplace(vertex, 0);
      this->Refinement.receivedPoints.push_back(vertex);
      ++this->Refinement.healedSplits;
    }
    else
    {
      vertex = this->createMidpoint(key, shareable);
    }
    this->Created.emplace(key, vertex);
    return vertex;
  }

  // Room for the splits this session expects to make, `shared` of them on interfaces.
  void reserve(std::size_t splits, std::size_t shared)
  {
    this->Created.reserve(splits);
    PartitionRefinement& r = this->Refinement;
    r.newPointSources.reserve(r.newPointSources.size() + splits);
    r.newCoordinates.reserve(r.newCoordinates.size() + 3 * splits);
    if (this->Context.sizes)
    {
      r.newSizes.reserve(r.newSizes.size() + splits);
    }
    r.outbox.reserve(r.outbox.size() + shared);
    r.newInterfacePoints.reserve(r.newInterfacePoints.size() + shared);
  }

  // Whether edge (a, b) may be shared with a neighbour: both ends on an interface.
  bool mayShare(PointId a, PointId b) const { return this->onInterface(a) && this->onInterface(b); }

  // Bit e set when the tet's edge e is long and the filter lets it be split.
  int splitMaskOf(const Tet& tet, const EdgeFilter& filter) const
  {
    int splitMask = 0;
    for (int e = 0; e < 6; ++e)
    {
      const PointId a = tet[TetEdgeCorners[e][0]];
      const PointId b = tet[TetEdgeCorners[e][1]];
      if (this->isLong(a, b) && filter.allows(EdgeKey::of(a, b)))
      {
        splitMask |= 1 << e;
      }
    }
    return splitMask;
  }

  // The slots midpointOf() will read among the posted splits for the tet's split edges (those
  // between two interface vertices), into `slots`; returns how many.
  int postedSlotsOf(const Tet& tet, int splitMask, const void* slots[6]) const
  {
    int count = 0;
    for (int e = 0; e < 6; ++e)
    {
      const PointId a = tet[TetEdgeCorners[e][0]];
      const PointId b = tet[TetEdgeCorners[e][1]];
      if (((splitMask >> e) & 1) && this->mayShare(a, b))
      {
        slots[count++] = this->Received.firstSlotOf(EdgeKey::of(a, b));
      }
    }
    return count;
  }

private:
  // `shareable`: both ends on an interface, so neighbours may hold the edge and heal the split.
  PointId createMidpoint(const EdgeKey& key, bool shareable)
  {
    // Copies: the end points may themselves be new, and the vector below may reallocate.
    double pa[3], pb[3];
    std::copy_n(this->coordinatesOf(key.low), 3, pa);
    std::copy_n(this->coordinatesOf(key.high), 3, pb);
    const PointId vertex = provisionalId(this->Refinement.newPointSources.size());
    for (int axis = 0; axis < 3; ++axis)
    {
      this->Refinement.newCoordinates.push_back(0.5 * (pa[axis] + pb[axis]));
    }
    this->Refinement.newPointSources.push_back(PointSource::midpoint(key));
    if (this->Context.sizes)
    {
      this->Refinement.newSizes.push_back(0.5 * (this->sizeOf(key.low) + this->sizeOf(key.high)));
    }
    ++this->Refinement.createdSplits;
    if (shareable)
    {
      this->Refinement.outbox.push_back(OutboxEntry{ key, vertex });
      this->Refinement.newInterfacePoints.emplace(vertex, 0);
    }
    return vertex;
  }

  // Whether a vertex may be shared with another partition (so may the edges between two such).
  bool onInterface(PointId id) const
  {
    const auto& flags = *this->Context.interfaceVertex;
    if (id >= 0 && id < static_cast<PointId>(flags.size()))
    {
      return flags[id] != 0;
    }
    return this->Refinement.newInterfacePoints.contains(id);
  }

  const RefinementContext& Context;
  const PostedSplits& Received;
  PartitionRefinement& Refinement;
  EdgeMidpointMap Created;
};

// The rank of each corner among the four in the order that decides face diagonals: the global
// vertex order (vertexRank()) or, across processes, the coordinates' lexicographic order.
template <typename CoordinatesOf>
std::array<int, 4> cornerRanks(
  const Tet& tet, const RefinementContext& context, const CoordinatesOf& coordinatesOf)
{
  auto precedes = [&](PointId a, PointId b)
  {
    if (!context.orderCornersByCoordinates)
    {
      return vertexRank(a) < vertexRank(b);
    }
    const double* pa = coordinatesOf(a);
    const double* pb = coordinatesOf(b);
    return std::lexicographical_compare(pa, pa + 3, pb, pb + 3);
  };
  std::array<int, 4> ranks;
  for (int i = 0; i < 4; ++i)
  {
    ranks[i] = 0;
    for (int j = 0; j < 4; ++j)
    {
      ranks[i] += precedes(tet[j], tet[i]);
    }
  }
  return ranks;
}

// For a fully split tet: the shortest of the three octahedron diagonals (ties: lowest index),
// which gives the best-shaped children.
int shortestDiagonal(const SplitSession& session, const std::array<PointId, 10>& vertices)
{
  const int axisEdge[3][2] = { { 0, 5 }, { 1, 4 }, { 2, 3 } };
  int best = 0;
  double bestLength = 0;
  for (int d = 0; d < 3; ++d)
  {
    const double length = squaredDistance(session.coordinatesOf(vertices[4 + axisEdge[d][0]]),
      session.coordinatesOf(vertices[4 + axisEdge[d][1]]));
    if (d == 0 || length < bestLength)
    {
      best = d;
      bestLength = length;
    }
  }
  return best;
}

// Bit k set: vertex i of a template's local numbering (the corners, then the midpoints of the
// edges in TetEdgeCorners' order) lies on the parent's face opposite corner k.
constexpr std::uint8_t ParentFacesOfLocalVertex[10] = { 0xE, 0xD, 0xB, 0x7, 0xC, 0xA, 0x6, 0x9, 0x5,
  0x3 };

// A child's constrained-face marks from its parent's: a child face lies in the parent face that
// holds all three of its vertices, if any.
std::uint8_t childFaceMarks(const LocalTet& child, std::uint8_t parentMarks)
{
  std::uint8_t marks = 0;
  for (int i = 0; i < 4; ++i)
  {
    const int onParentFaces = ParentFacesOfLocalVertex[child[(i + 1) & 3]] &
      ParentFacesOfLocalVertex[child[(i + 2) & 3]] & ParentFacesOfLocalVertex[child[(i + 3) & 3]];
    if (onParentFaces & parentMarks)
    {
      marks |= 1 << i;
    }
    if (onParentFaces & (parentMarks >> InterfaceMarkShift))
    {
      marks |= 1 << (InterfaceMarkShift + i);
    }
  }
  return marks;
}

} // namespace

Status findInterfaceVertices(const std::vector<PartitionMesh>& partitions, PointId numberOfPoints,
  const ParallelFor& parallelFor, std::vector<char>& interfaceVertex)
{
  // Partitions are scanned concurrently: the first to reach a point claims it (owner: partition
  // + 1, 0 while unclaimed), and any other partition that holds it marks it. Which partition
  // claims a point depends on the schedule; whether a second one holds it does not.
  std::vector<std::atomic<int>> owner(numberOfPoints);
  std::vector<std::atomic<unsigned char>> shared(numberOfPoints);
  Status status = parallelFor(static_cast<std::int64_t>(partitions.size()),
    [&](std::int64_t part)
    {
      const int mine = static_cast<int>(part) + 1;
      for (const Tet& tet : partitions[part].tets)
      {
        for (PointId p : tet)
        {
          // A failed claim leaves the claiming partition in `seen`: another one, as each
          // partition is a single task.
          int seen = owner[p].load(std::memory_order_relaxed);
          if (seen == mine ||
            (seen == 0 && owner[p].compare_exchange_strong(seen, mine, std::memory_order_relaxed)))
          {
            continue;
          }
          shared[p].store(1, std::memory_order_relaxed);
        }
      }
    });
  if (!status.ok())
  {
    return status;
  }
  interfaceVertex.resize(numberOfPoints);
  return forEachRange(parallelFor, numberOfPoints, IndicesPerCopyRange,
    [&](std::int64_t begin, std::int64_t end)
    {
      for (std::int64_t p = begin; p < end; ++p)
      {
        interfaceVertex[p] = static_cast<char>(shared[p].load(std::memory_order_relaxed));
      }
    });
}

std::int64_t predictTemplateTetCount(
  const PartitionMesh& partition, const RefinementContext& context)
{
  std::int64_t count = 0;
  const std::vector<double>& coordinates = *context.coordinates;
  for (const Tet& tet : partition.tets)
  {
    int splitMask = 0;
    for (int e = 0; e < 6; ++e)
    {
      const PointId a = tet[TetEdgeCorners[e][0]], b = tet[TetEdgeCorners[e][1]];
      const double lengthSquared = squaredDistance(
        coordinates.data() + 3 * std::min(a, b), coordinates.data() + 3 * std::max(a, b));
      const bool isLong = context.sizes
        ? longerThanSize(lengthSquared, (*context.sizes)[a], (*context.sizes)[b])
        : lengthSquared > context.squaredThreshold;
      splitMask |= isLong << e;
    }
    count += splitMask == 0 ? 1
      : splitMask == 63
      ? 8
      : static_cast<std::int64_t>(
          context.templates
            ->partialSplit(splitMask,
              cornerRanks(
                tet, context, [&coordinates](PointId id) { return coordinates.data() + 3 * id; }))
            .size());
  }
  return count;
}

Status refinePartition(PartitionMesh& partition, const RefinementContext& context,
  const PostedSplits& received, PartitionRefinement& refinement, const EdgeFilter& filter,
  std::vector<std::size_t>* origins, ConstrainedFaceMarks* faceMarks,
  std::vector<char>* passedUnsplit)
{
  try
  {
    SplitSession session(context, received, refinement);
    const bool listsTetsToScreen = context.improvementTarget > 0;
    refinement.tetsToScreen.clear();
    // Cubed mean ratios a fully split parent must reach for its corner children (the parent
    // halved) and for all its children to clear the target; a hair above the bounds, so that
    // rounding in the midpoints cannot put a child just under it.
    const double cornersClearAt = std::pow(context.improvementTarget * (1 + 1e-9), 3);
    const double allClearAt =
      std::pow(context.improvementTarget / FullSplitChildQuality * (1 + 1e-9), 3);
    const bool hasRegions = !partition.regions.empty();
    // Split patterns first: the most children they give sizes the refined mesh at once, and the
    // loop below prefetches the posted splits of the tet a few places ahead. At 65,536 partitions
    // of 16 tets nearly every edge is shared, and half the loop's time went in waiting for the
    // look-ups.
    const std::size_t tetCount = partition.tets.size();
    std::vector<std::uint8_t> splitMasks(tetCount);
    std::size_t mostTets = 0, splitEdges = 0, sharedSplitEdges = 0; // counted once per tet
    // Tets known to have no long edge are not measured: on the FinFET with its size field, six
    // passes measured the edges of 23 M tets for 1.8 M split.
    const bool knownUnsplit = passedUnsplit && passedUnsplit->size() == tetCount;
    for (std::size_t t = 0; t < tetCount; ++t)
    {
      const Tet& tet = partition.tets[t];
      if (knownUnsplit && (*passedUnsplit)[t])
      {
        ++mostTets; // mask 0: the tet itself
        continue;
      }
      const int splitMask = session.splitMaskOf(tet, filter);
      splitMasks[t] = static_cast<std::uint8_t>(splitMask);
      mostTets += context.templates->mostChildren(splitMask);
      for (int e = 0; e < 6; ++e)
      {
        if ((splitMask >> e) & 1)
        {
          ++splitEdges;
          sharedSplitEdges +=
            session.mayShare(tet[TetEdgeCorners[e][0]], tet[TetEdgeCorners[e][1]]);
        }
      }
    }
    // A tet mesh has about 7/6 edges per tet, a small partition more (its surface's edges are
    // shared by fewer tets): room for twice the tets plus 64 new points, or for the split edges
    // counted per tet where those are fewer (they bound the new points). A partition that makes
    // more grows its tables as before.
    const std::size_t expectedSplits = std::min(splitEdges, 2 * tetCount + 64);
    session.reserve(expectedSplits, std::min(sharedSplitEdges, expectedSplits));
    PartitionMesh refined;
    refined.tets.reserve(mostTets);
    refined.parentCells.reserve(mostTets);
    if (hasRegions)
    {
      refined.regions.reserve(mostTets);
    }
    if (origins)
    {
      origins->clear();
      origins->reserve(mostTets);
    }
    ConstrainedFaceMarks childMarks;
    if (faceMarks)
    {
      childMarks.reserve(mostTets);
    }
    std::vector<char> unsplit;
    if (passedUnsplit)
    {
      unsplit.reserve(mostTets);
    }
    // Lists the tet that goes to position `index` of the refined partition when its mean ratio is
    // below the target: measured here, while its corners' coordinates are at hand, improvement
    // screens it alone.
    auto listIfPoor = [&](const Tet& tet, std::size_t index)
    {
      if (meanRatioBelow(session.coordinatesOf(tet[0]), session.coordinatesOf(tet[1]),
            session.coordinatesOf(tet[2]), session.coordinatesOf(tet[3]),
            context.improvementTarget))
      {
        refinement.tetsToScreen.push_back(index);
      }
    };
    constexpr std::size_t PrefetchDistance = 8; // tets
    std::size_t prefetched = 0; // the tets before it have had their posted splits prefetched
    for (std::size_t t = 0; t < tetCount; ++t)
    {
      // Each tet prefetches for the tets up to PrefetchDistance places ahead not yet done: the
      // first for the first PrefetchDistance + 1, most others for one. The prefetch stays written
      // out here: GCC drops calls to a function or lambda that does nothing but prefetch.
      for (; prefetched <= t + PrefetchDistance && prefetched < tetCount; ++prefetched)
      {
        const void* slots[6];
        const int count =
          session.postedSlotsOf(partition.tets[prefetched], splitMasks[prefetched], slots);
        for (int k = 0; k < count; ++k)
        {
          __builtin_prefetch(slots[k]);
        }
      }
      // A run of tets that stay whole is copied at once: in the later passes of a size field
      // most tets are.
      if (splitMasks[t] == 0)
      {
        std::size_t end = t + 1;
        while (end < tetCount && splitMasks[end] == 0)
        {
          ++end;
        }
        for (std::size_t whole = t; listsTetsToScreen && whole < end; ++whole)
        {
          listIfPoor(partition.tets[whole], refined.tets.size() + (whole - t));
        }
        const auto from = [t](const auto& values)
        {
          return values.begin() + t;
        };
        const auto to = [end](const auto& values)
        {
          return values.begin() + end;
        };
        refined.tets.insert(refined.tets.end(), from(partition.tets), to(partition.tets));
        refined.parentCells.insert(
          refined.parentCells.end(), from(partition.parentCells), to(partition.parentCells));
        if (hasRegions)
        {
          refined.regions.insert(
            refined.regions.end(), from(partition.regions), to(partition.regions));
        }
        for (std::size_t whole = t; origins && whole < end; ++whole)
        {
          origins->push_back(whole);
        }
        if (faceMarks)
        {
          childMarks.insert(childMarks.end(), from(*faceMarks), to(*faceMarks));
        }
        if (passedUnsplit)
        {
          unsplit.insert(unsplit.end(), end - t, 1);
        }
        t = end - 1;
        continue;
      }
      const Tet& tet = partition.tets[t];
      std::array<PointId, 10> vertices = { tet[0], tet[1], tet[2], tet[3] };
      const int splitMask = splitMasks[t];
      for (int e = 0; e < 6; ++e)
      {
        if ((splitMask >> e) & 1)
        {
          vertices[4 + e] =
            session.midpointOf(tet[TetEdgeCorners[e][0]], tet[TetEdgeCorners[e][1]]);
        }
      }
      auto emit = [&](const Tet& child)
      {
        refined.tets.push_back(child);
        refined.parentCells.push_back(partition.parentCells[t]);
        if (hasRegions)
        {
          refined.regions.push_back(partition.regions[t]);
        }
      };
      const std::vector<LocalTet>& children = splitMask == 63
        ? context.templates->fullSplit(shortestDiagonal(session, vertices))
        : context.templates->partialSplit(splitMask,
            cornerRanks(
              tet, context, [&session](PointId id) { return session.coordinatesOf(id); }));
      const double parentQuality = listsTetsToScreen && splitMask == 63
        ? cubedMeanRatio(session.coordinatesOf(tet[0]), session.coordinatesOf(tet[1]),
            session.coordinatesOf(tet[2]), session.coordinatesOf(tet[3]))
        : 0;
      for (const LocalTet& child : children)
      {
        const bool isCorner = child[0] < 4 || child[1] < 4 || child[2] < 4 || child[3] < 4;
        const Tet corners = { vertices[child[0]], vertices[child[1]], vertices[child[2]],
          vertices[child[3]] };
        if (listsTetsToScreen && parentQuality < (isCorner ? cornersClearAt : allClearAt))
        {
          listIfPoor(corners, refined.tets.size());
        }
        emit(corners);
        if (faceMarks)
        {
          childMarks.push_back(childFaceMarks(child, (*faceMarks)[t]));
        }
      }
      if (origins)
      {
        origins->insert(origins->end(), children.size(), t);
      }
      if (passedUnsplit)
      {
        unsplit.insert(unsplit.end(), children.size(), 0);
      }
    }
    partition = std::move(refined);
    if (faceMarks)
    {
      faceMarks->swap(childMarks);
    }
    if (passedUnsplit)
    {
      passedUnsplit->swap(unsplit);
    }
  }
  catch (const std::bad_alloc&)
  {
    return Status::failure(ErrorKind::OutOfMemory, "out of memory while refining a partition");
  }
  return Status::success();
}

void finalizeNewPoints(
  PartitionMesh& partition, PartitionRefinement& refinement, PointId firstGlobalId)
{
  // Released, not cleared: every partition's refinement stays alive until the pass ends, and
  // cleared sets kept their slots (at 65,536 partitions of 16 tets, where nearly every new point
  // lies on an interface, hundreds of megabytes that later partitions then took as fresh pages).
  refinement.newInterfacePoints = PointIdSet();
  if (refinement.newPointSources.empty())
  {
    return; // it made no point, so every id it holds is global already
  }
  auto globalId = [firstGlobalId](PointId id)
  {
    return finalId(id, firstGlobalId);
  };
  for (Tet& tet : partition.tets)
  {
    for (PointId& id : tet)
    {
      id = globalId(id);
    }
  }
  for (OutboxEntry& entry : refinement.outbox)
  {
    entry.edge = EdgeKey::of(globalId(entry.edge.low), globalId(entry.edge.high));
    entry.vertex = globalId(entry.vertex);
  }
  for (PointId& point : refinement.movedPoints)
  {
    point = globalId(point);
  }
  for (PointSource& source : refinement.newPointSources)
  {
    for (int slot = 0; slot < 4; ++slot)
    {
      if (source.weights[slot] != 0)
      {
        source.points[slot] = globalId(source.points[slot]);
      }
    }
  }
}

} // namespace cgmesh
