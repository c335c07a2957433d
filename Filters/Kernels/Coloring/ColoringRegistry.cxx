// The list of colourings: adding one is a new file plus one line in `registry()`.
#include "Coloring/GreedyColoring.h"
#include "Coloring/GreedyLeastUsedColoring.h"
#include "Coloring/IterativeColoring.h"
#include "Coloring/PartitionColoring.h"
#include "Coloring/RecoloringBalance.h"

#include <algorithm>

namespace cgmesh
{
namespace
{

struct RegisteredColoring
{
  const char* name;
  std::unique_ptr<PartitionColoring> (*make)();
};

template <typename T>
std::unique_ptr<PartitionColoring> makeInstance()
{
  return std::make_unique<T>();
}

const std::vector<RegisteredColoring>& registry()
{
  static const std::vector<RegisteredColoring> colorings = {
    { "greedy", &makeInstance<GreedyColoring> },
    { "greedy-lu", &makeInstance<GreedyLeastUsedColoring> },
    { "iterative", &makeInstance<IterativeColoring> },
    { "recoloring", &makeInstance<RecoloringBalance> },
  };
  return colorings;
}

} // namespace

std::unique_ptr<PartitionColoring> makeColoring(const std::string& name)
{
  for (const RegisteredColoring& entry : registry())
  {
    if (name == entry.name)
    {
      return entry.make();
    }
  }
  return nullptr;
}

std::vector<std::string> coloringNames()
{
  std::vector<std::string> names;
  for (const RegisteredColoring& entry : registry())
  {
    names.emplace_back(entry.name);
  }
  return names;
}

bool isProperColoring(const PartitionGraph& graph, const std::vector<int>& colorOfPartition)
{
  if (static_cast<int>(colorOfPartition.size()) != graph.numberOfPartitions)
  {
    return false;
  }
  for (int p = 0; p < graph.numberOfPartitions; ++p)
  {
    if (colorOfPartition[p] < 0)
    {
      return false;
    }
    const int* neighbours = graph.neighboursOf(p);
    for (int i = 0; i < graph.degree(p); ++i)
    {
      if (colorOfPartition[neighbours[i]] == colorOfPartition[p])
      {
        return false;
      }
    }
  }
  return true;
}

int countColors(const std::vector<int>& colorOfPartition)
{
  return colorOfPartition.empty()
    ? 0
    : 1 + *std::max_element(colorOfPartition.begin(), colorOfPartition.end());
}

} // namespace cgmesh
