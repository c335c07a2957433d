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
    // Each outbox's entries grouped by shard (a stable counting sort), then each shard fed from
    // its group of every outbox.
    std::vector<std::array<std::size_t, Shards + 1>> groupStart(outboxes.size());
    std::vector<std::vector<const OutboxEntry*>> grouped(outboxes.size());
    Status status = parallelFor(static_cast<std::int64_t>(outboxes.size()),
      [&](std::int64_t i)
      {
        const Outbox& outbox = *outboxes[i];
        std::array<std::size_t, Shards + 1>& start = groupStart[i];
        start.fill(0);
        for (const OutboxEntry& entry : outbox)
        {
          ++start[shardOf(entry.edge) + 1];
        }
        for (int s = 0; s < Shards; ++s)
        {
          start[s + 1] += start[s];
        }
        std::array<std::size_t, Shards> next;
        std::copy(start.begin(), start.end() - 1, next.begin());
        grouped[i].resize(outbox.size());
        for (const OutboxEntry& entry : outbox)
        {
          grouped[i][next[shardOf(entry.edge)]++] = &entry;
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
        std::vector<const OutboxEntry*> incoming;
        for (std::size_t i = 0; i < grouped.size(); ++i)
        {
          incoming.insert(incoming.end(), grouped[i].begin() + groupStart[i][s],
            grouped[i].begin() + groupStart[i][s + 1]);
        }
        shard.reserve(shard.size() + incoming.size());
        // Each insertion's slot is fetched a few entries ahead: the shard is large, and with
        // partitions of a few tets (short runs per outbox) the inserts waited on memory in turn.
        constexpr std::size_t PrefetchDistance = 8;
        for (std::size_t k = 0; k < incoming.size(); ++k)
        {
          if (k + PrefetchDistance < incoming.size())
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
