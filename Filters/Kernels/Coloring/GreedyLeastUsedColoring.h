// Greedy-LU: the palette size of first-fit greedy, then a second pass that gives each partition
// the least-used colour its neighbours allow. Serial, balanced populations.
#ifndef cgmesh_GreedyLeastUsedColoring_h
#define cgmesh_GreedyLeastUsedColoring_h

#include "Coloring/PartitionColoring.h"

namespace cgmesh
{

class GreedyLeastUsedColoring : public PartitionColoring
{
public:
  const char* name() const override { return "greedy-lu"; }
  Status color(const PartitionGraph& graph, const ParallelFor& parallelFor,
    std::vector<int>& colorOfPartition) const override;
};

} // namespace cgmesh

#endif
