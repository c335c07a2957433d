// Scratch shared by the colourings: the set of colours a partition may not take, cleared in O(1)
// by stamping instead of resetting.
#ifndef cgmesh_ColoringSupport_h
#define cgmesh_ColoringSupport_h

#include <cstdint>
#include <vector>

namespace cgmesh
{

class ForbiddenColors
{
public:
  // Starts a new, empty set.
  void clear() { ++this->Stamp; }

  void forbid(int color)
  {
    if (color < 0)
    {
      return;
    }
    if (color >= static_cast<int>(this->StampOf.size()))
    {
      this->StampOf.resize(color + 1, 0);
    }
    this->StampOf[color] = this->Stamp;
  }

  bool isForbidden(int color) const
  {
    return color < static_cast<int>(this->StampOf.size()) && this->StampOf[color] == this->Stamp;
  }

  int firstAllowed() const
  {
    int color = 0;
    while (this->isForbidden(color))
    {
      ++color;
    }
    return color;
  }

private:
  std::vector<std::uint64_t> StampOf;
  std::uint64_t Stamp = 1;
};

// Marks the colours of partition p's neighbours (uncoloured ones, -1, are skipped).
template <typename Graph>
void forbidNeighbourColors(
  const Graph& graph, int p, const std::vector<int>& colorOfPartition, ForbiddenColors& forbidden)
{
  forbidden.clear();
  const int* neighbours = graph.neighboursOf(p);
  for (int i = 0; i < graph.degree(p); ++i)
  {
    forbidden.forbid(colorOfPartition[neighbours[i]]);
  }
}

// Population of each colour: number of partitions that carry it.
inline std::vector<std::int64_t> colorSizes(const std::vector<int>& colorOfPartition, int colors)
{
  std::vector<std::int64_t> sizes(colors, 0);
  for (int c : colorOfPartition)
  {
    ++sizes[c];
  }
  return sizes;
}

} // namespace cgmesh

#endif
