// First-fit greedy colouring in partition order: few colours, unbalanced populations.
#ifndef cgmesh_GreedyColoring_h
#define cgmesh_GreedyColoring_h

#include "Coloring/PartitionColoring.h"

namespace cgmesh
{

class GreedyColoring : public PartitionColoring
{
public:
  const char* name() const override { return "greedy"; }
  Status color(const PartitionGraph& graph, const ParallelFor& parallelFor,
    std::vector<int>& colorOfPartition) const override;
};

} // namespace cgmesh

#endif
