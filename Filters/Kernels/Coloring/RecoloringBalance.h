// Balancing by recolouring (after Lu et al. 2015, "scheduled reverse" moves): start from the
// first-fit greedy colouring, then visit its colour classes from the last to the first and move
// partitions out of over-full classes into the least-used colour their neighbours allow.
//
// Partitions of one class are never adjacent, so while a class is visited its members' allowed
// colours depend only on other classes, which stand still: those sets are computed in parallel.
// The moves are then decided serially in partition id order, which makes the result independent
// of the thread count.
#ifndef cgmesh_RecoloringBalance_h
#define cgmesh_RecoloringBalance_h

#include "Coloring/PartitionColoring.h"

namespace cgmesh
{

class RecoloringBalance : public PartitionColoring
{
public:
  const char* name() const override { return "recoloring"; }
  Status color(const PartitionGraph& graph, const ParallelFor& parallelFor,
    std::vector<int>& colorOfPartition) const override;
};

} // namespace cgmesh

#endif
