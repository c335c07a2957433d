// Disjoint sets over 0..n-1 whose root is always the lowest member of its set: what a series of
// unions leaves does not depend on their order, so clusterings built from it are deterministic
// whatever order the pairs arrive in. Lookups halve the path to the root as they go.
#ifndef cgmesh_LowestRootSets_h
#define cgmesh_LowestRootSets_h

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace cgmesh
{

template <typename Index>
class LowestRootSets
{
public:
  explicit LowestRootSets(std::size_t count)
    : Parent(count)
  {
    std::iota(this->Parent.begin(), this->Parent.end(), Index(0));
  }

  Index root(Index i)
  {
    while (this->Parent[i] != i)
    {
      this->Parent[i] = this->Parent[this->Parent[i]];
      i = this->Parent[i];
    }
    return i;
  }

  // Joins the sets of a and b; returns the root of the union.
  Index join(Index a, Index b)
  {
    const Index first = this->root(a), second = this->root(b);
    const Index lowest = std::min(first, second);
    this->Parent[std::max(first, second)] = lowest;
    return lowest;
  }

private:
  std::vector<Index> Parent;
};

} // namespace cgmesh

#endif
