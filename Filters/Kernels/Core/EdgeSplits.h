// Edge keys, outboxes and the maps that tell a partition which of its edges already have a
// midpoint: the data that crosses partition interfaces.
#ifndef cgmesh_EdgeSplits_h
#define cgmesh_EdgeSplits_h

#include "Core/FlatHashMap.h"
#include "Core/TetMesh.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <limits>
#include <vector>

namespace cgmesh
{

// An undirected edge between two global point ids, stored with the smaller id first.
struct EdgeKey
{
  PointId low;
  PointId high;

  static EdgeKey of(PointId a, PointId b) { return a < b ? EdgeKey{ a, b } : EdgeKey{ b, a }; }
  bool operator==(const EdgeKey& other) const { return low == other.low && high == other.high; }
};

struct EdgeKeyHash
{
  std::size_t operator()(const EdgeKey& key) const
  {
    // splitmix64-style mixing: point ids are dense, so a plain xor would collide heavily.
    std::uint64_t x = static_cast<std::uint64_t>(key.low) * 0x9E3779B97F4A7C15ull ^
      static_cast<std::uint64_t>(key.high);
    x ^= x >> 31;
    x *= 0xBF58476D1CE4E5B9ull;
    x ^= x >> 29;
    return static_cast<std::size_t>(x);
  }
};

// Where a new vertex lies: a weighted sum of up to four existing vertices (unused slots have
// weight 0). An edge midpoint has two halves; a Delaunay Steiner point the barycentric
// coordinates of the tet it was inserted in. Point data is interpolated with these weights.
struct PointSource
{
  std::array<PointId, 4> points;
  std::array<double, 4> weights;

  static PointSource midpoint(const EdgeKey& edge)
  {
    return { { edge.low, edge.high, -1, -1 }, { 0.5, 0.5, 0, 0 } };
  }
};

struct NoEdge
{
  static EdgeKey value()
  {
    return { std::numeric_limits<PointId>::min(), std::numeric_limits<PointId>::min() };
  }
};

// Midpoint vertex of each split edge.
using EdgeMidpointMap = FlatHashMap<EdgeKey, PointId, EdgeKeyHash, NoEdge>;

struct PointIdHash
{
  std::size_t operator()(PointId id) const
  {
    std::uint64_t x = static_cast<std::uint64_t>(id) * 0x9E3779B97F4A7C15ull;
    return static_cast<std::size_t>(x ^ (x >> 32));
  }
};

struct NoPoint
{
  static PointId value() { return std::numeric_limits<PointId>::min(); }
};

// A map from point ids, and a set of them (the value unused).
template <typename Value>
using PointIdMap = FlatHashMap<PointId, Value, PointIdHash, NoPoint>;
using PointIdSet = PointIdMap<char>;

// One split of an edge that may be shared with partitions processed later in the same iteration:
// the edge's two global end points and the global id of the vertex inserted on it.
struct OutboxEntry
{
  EdgeKey edge;
  PointId vertex;
};

using Outbox = std::vector<OutboxEntry>;

} // namespace cgmesh

#endif
