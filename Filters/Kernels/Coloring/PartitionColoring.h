// Colouring of the partition graph into independent sets: partitions of one colour share no
// vertex and can be refined concurrently. Each algorithm is one class in its own file, registered
// in ColoringRegistry.cxx.
#ifndef cgmesh_PartitionColoring_h
#define cgmesh_PartitionColoring_h

#include "Core/Status.h"
#include "Partitioning/PartitionGraph.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace cgmesh
{

// Runs body(i) for every i in [0, count), possibly concurrently, and returns a failure when a call
// threw. Supplied by the driver, which owns the threads, so that colourings with parallel rounds
// stay free of any threading library. A colouring returns such a failure as it is.
using ParallelFor =
  std::function<Status(std::int64_t count, const std::function<void(std::int64_t)>& body)>;

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
