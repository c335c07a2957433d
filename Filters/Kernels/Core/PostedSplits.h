// The interface splits processed partitions posted in one iteration: what the partitions
// processed after them heal from, looked up by edge. A partition only ever looks up edges it
// holds, and an edge it shares was split by a neighbour, so one map for all processed partitions
// serves every later one, with each split in it once.
//
// The map is cut into shards by the edge's hash, so that a colour's splits are added by one task
// per shard instead of one after another: on the Big cube (2 iterations, 1024 partitions) adding
// them serially took 0.06 s, the same at any thread count.
#ifndef cgmesh_PostedSplits_h
#define cgmesh_PostedSplits_h

#include "Core/EdgeSplits.h"
#include "Core/Status.h"
#include "Core/Tasks.h"

#include <array>
#include <cstddef>
#include <vector>

namespace cgmesh
{

class PostedSplits
{
public:
  static constexpr int Shards = 16;

  // The midpoint of `key`, or null when no processed partition split it.
  const PointId* find(const EdgeKey& key) const { return this->Map[shardOf(key)].find(key); }

  // The slot find(key) reads first, to prefetch (FlatHashMap::firstSlotOf).
  const void* firstSlotOf(const EdgeKey& key) const
  {
    return this->Map[shardOf(key)].firstSlotOf(key);
  }

  std::size_t size() const
  {
    std::size_t total = 0;
    for (const EdgeMidpointMap& shard : this->Map)
    {
      total += shard.size();
    }
    return total;
  }

  // Adds the splits of `outboxes` (global ids). Each shard takes its entries in outbox order,
  // whatever `parallelFor` runs concurrently, so the maps are the same for any thread count.
  Status post(const std::vector<const Outbox*>& outboxes, const ParallelFor& parallelFor)
  {
    // One counting sort of every outbox's entries by shard into a single array: each outbox
    // counts its entries per shard, the counts give every (shard, outbox) group its place, and the
    // outboxes scatter their entries there; then each shard is fed from its stretch. With
    // 65,536 partitions of 16 tets, a group array per outbox and a gathered copy per shard made
    // two allocations per partition and colour and a second pass over the entries.
    const std::size_t count = outboxes.size();
    std::vector<std::array<std::size_t, Shards>> place(count); // counts, then each group's start
    Status status = parallelFor(static_cast<std::int64_t>(count),
      [&](std::int64_t i)
      {
        place[i].fill(0);
        for (const OutboxEntry& entry : *outboxes[i])
        {
          ++place[i][shardOf(entry.edge)];
        }
      });
    if (!status.ok())
    {
      return status;
    }
    std::array<std::size_t, Shards + 1> shardStart{};
    std::size_t total = 0;
    for (int s = 0; s < Shards; ++s)
    {
      shardStart[s] = total;
      for (std::size_t i = 0; i < count; ++i)
      {
        const std::size_t entries = place[i][s];
        place[i][s] = total;
        total += entries;
      }
    }
    shardStart[Shards] = total;
    std::vector<const OutboxEntry*> grouped(total);
    status = parallelFor(static_cast<std::int64_t>(count),
      [&](std::int64_t i)
      {
        std::array<std::size_t, Shards>& next = place[i];
        for (const OutboxEntry& entry : *outboxes[i])
        {
          grouped[next[shardOf(entry.edge)]++] = &entry;
        }
      });
    if (!status.ok())
    {
      return status;
    }
    return parallelFor(Shards,
      [&](std::int64_t s)
      {
        EdgeMidpointMap& shard = this->Map[s];
        const OutboxEntry* const* incoming = grouped.data() + shardStart[s];
        const std::size_t entries = shardStart[s + 1] - shardStart[s];
        shard.reserve(shard.size() + entries);
        // Each insertion's slot is fetched a few entries ahead: the shard is large, and with
        // partitions of a few tets (short runs per outbox) the inserts waited on memory in turn.
        constexpr std::size_t PrefetchDistance = 8;
        for (std::size_t k = 0; k < entries; ++k)
        {
          if (k + PrefetchDistance < entries)
          {
            __builtin_prefetch(shard.firstSlotOf(incoming[k + PrefetchDistance]->edge));
          }
          shard.emplace(incoming[k]->edge, incoming[k]->vertex);
        }
      });
  }

  // The same for one outbox, on the calling thread.
  void post(const Outbox& outbox) { this->post({ &outbox }, ParallelFor(runSerially)); }

private:
  // The hash's top bits: each shard's table indexes by its low bits.
  static std::size_t shardOf(const EdgeKey& key) { return EdgeKeyHash()(key) >> 60; }

  std::array<EdgeMidpointMap, Shards> Map;
};

} // namespace cgmesh

#endif
