// The alive tets at each of the improver's vertices (Improver.h). One array holds every list, each
// in a range sized when built at its vertex's tets plus some room, so that building allocates
// once instead of once per vertex (a few hundred thousand lists on the FinFET's neighbourhoods,
// their allocations and frees a twentieth of improvement). A list that outgrows its range moves
// to a vector of its own; no other list ever moves, so a list being read stays valid while the
// others change. Internal to the Improvement kernels.
#ifndef cgmesh_IncidenceLists_h
#define cgmesh_IncidenceLists_h

#include <algorithm>
#include <cstddef>
#include <vector>

namespace cgmesh
{
namespace improvement
{

class IncidenceLists
{
public:
  // A read-only view of one list, valid until that list changes.
  class List
  {
  public:
    List(const int* first, const int* last)
      : First(first)
      , Last(last)
    {
    }
    // Any tets in a vector, for the functions that take a list of tets.
    List(const std::vector<int>& tets)
      : First(tets.data())
      , Last(tets.data() + tets.size())
    {
    }
    const int* begin() const { return this->First; }
    const int* end() const { return this->Last; }
    std::size_t size() const { return static_cast<std::size_t>(this->Last - this->First); }
    bool empty() const { return this->First == this->Last; }
    int front() const { return *this->First; }

  private:
    const int* First;
    const int* Last;
  };

  // Empty lists for vertices 0 to counts.size() - 1, with room for counts[v] + room tets each.
  void reserve(const std::vector<int>& counts, int room)
  {
    const std::size_t vertices = counts.size();
    this->Start.resize(vertices + 1);
    this->Start[0] = 0;
    for (std::size_t v = 0; v < vertices; ++v)
    {
      this->Start[v + 1] = this->Start[v] + static_cast<std::size_t>(counts[v] + room);
    }
    this->Slots.resize(this->Start[vertices]);
    this->Size.assign(vertices, 0);
    this->Own.assign(vertices, -1);
  }

  List operator[](int v) const
  {
    if (this->Own[v] >= 0)
    {
      const std::vector<int>& own = this->Owned[this->Own[v]];
      return List(own.data(), own.data() + own.size());
    }
    const int* first = this->Slots.data() + this->Start[v];
    return List(first, first + this->Size[v]);
  }

  void add(int v, int t)
  {
    if (this->Own[v] >= 0)
    {
      this->Owned[this->Own[v]].push_back(t);
      return;
    }
    const std::size_t at = this->Start[v] + static_cast<std::size_t>(this->Size[v]);
    if (at < this->Start[v + 1])
    {
      this->Slots[at] = t;
      ++this->Size[v];
      return;
    }
    // Full: the list moves to a vector of its own, with twice its length as room.
    this->Own[v] = static_cast<int>(this->Owned.size());
    this->Owned.emplace_back();
    std::vector<int>& own = this->Owned.back();
    own.reserve(2 * static_cast<std::size_t>(this->Size[v]) + 1);
    own.assign(this->Slots.begin() + static_cast<std::ptrdiff_t>(this->Start[v]),
      this->Slots.begin() + static_cast<std::ptrdiff_t>(at));
    own.push_back(t);
  }

  // Takes t out of v's list; the others keep their order.
  void remove(int v, int t)
  {
    if (this->Own[v] >= 0)
    {
      std::vector<int>& own = this->Owned[this->Own[v]];
      own.erase(std::remove(own.begin(), own.end(), t), own.end());
      return;
    }
    int* first = this->Slots.data() + this->Start[v];
    int* last = std::remove(first, first + this->Size[v], t);
    this->Size[v] = static_cast<int>(last - first);
  }

private:
  std::vector<int> Slots;         // every list in its range
  std::vector<std::size_t> Start; // per vertex, where its range begins; one more at the end
  std::vector<int> Size;          // per vertex, how many of its range's slots it uses
  std::vector<int> Own;           // per vertex, its index in Owned once it outgrew its range
  std::vector<std::vector<int>> Owned;
};

} // namespace improvement
} // namespace cgmesh

#endif
