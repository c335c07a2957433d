// Colouring of the partition graph into independent sets: partitions of one colour share no
// vertex and can be refined concurrently. Each algorithm is one class in its own file, registered
// in ColoringRegistry.cxx.
#ifndef cgmesh_PartitionColoring_h
#define cgmesh_PartitionColoring_h

#include "Core/Status.h"
#include "Core/Tasks.h"
#include "Partitioning/PartitionGraph.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace cgmesh
{

// Colourings with parallel rounds get a ParallelFor (Core/Tasks.h) from the driver and return its
// failures as they are.

class PartitionColoring
{
public:
  virtual ~PartitionColoring() = default;
  virtual const char* name() const = 0;
  // Fills colorOfPartition with colours 0..C-1 such that adjacent partitions differ. The result
  // must not depend on how parallelFor schedules its work.
  virtual Status color(const PartitionGraph& graph, const ParallelFor& parallelFor,
    std::vector<int>& colorOfPartition) const = 0;
};

// Returns nullptr for an unknown name.
std::unique_ptr<PartitionColoring> makeColoring(const std::string& name);
std::vector<std::string> coloringNames();

bool isProperColoring(const PartitionGraph& graph, const std::vector<int>& colorOfPartition);
int countColors(const std::vector<int>& colorOfPartition);

} // namespace cgmesh

#endif
