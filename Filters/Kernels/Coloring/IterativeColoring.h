// Speculative parallel colouring with conflict detection rounds (after Çatalyürek et al. 2012).
//
// Each round colours the pending partitions block by block in parallel. A block is a fixed range
// of partition ids (independent of the thread count); inside it partitions are coloured first-fit
// in id order, seeing the block's own fresh colours and every other block's colours as they were
// when the round began (a snapshot). Conflicts can therefore only arise across blocks; of two
// conflicting partitions the one with the larger id is coloured again in the next round. Every
// value a task reads is fixed before the round starts or written by the same task, so the result
// is the same for any number of threads and any schedule.
#ifndef cgmesh_IterativeColoring_h
#define cgmesh_IterativeColoring_h

#include "Coloring/PartitionColoring.h"

namespace cgmesh
{

class IterativeColoring : public PartitionColoring
{
public:
  explicit IterativeColoring(int blockSize = 64)
    : BlockSize(blockSize)
  {
  }
  const char* name() const override { return "iterative"; }
  Status color(const PartitionGraph& graph, const ParallelFor& parallelFor,
    std::vector<int>& colorOfPartition) const override;

private:
  int BlockSize;
};

} // namespace cgmesh

#endif
