// Face keys: the three corners of a tet face in ascending order, under which both tets sharing a
// face find it (dual graph, constrained faces, TetGen output validation).
#ifndef cgmesh_FaceKey_h
#define cgmesh_FaceKey_h

#include "Core/TetMesh.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace cgmesh
{

using Face = std::array<PointId, 3>; // corners in ascending order

// The corners of the face opposite corner `skip`, in ascending order: the key under which both
// tets sharing a face find it.
template <typename Index>
std::array<Index, 3> sortedFace(const Index* corners, int skip)
{
  // The three corners after `skip`, cyclically, then a three-element sorting network: this runs
  // four times per tet in every face search, where a general sort's call was 3% of a run.
  Index a = corners[(skip + 1) & 3], b = corners[(skip + 2) & 3], c = corners[(skip + 3) & 3];
  if (b < a)
  {
    std::swap(a, b);
  }
  if (c < b)
  {
    std::swap(b, c);
    if (b < a)
    {
      std::swap(a, b);
    }
  }
  return { a, b, c };
}

// The corner of `tet` opposite `face`, one of its faces: the corner the face lacks.
template <typename Index>
int cornerOpposite(const std::array<Index, 4>& tet, const std::array<Index, 3>& face)
{
  int corner = 0;
  while (std::find(face.begin(), face.end(), tet[corner]) != face.end())
  {
    ++corner;
  }
  return corner;
}

// Calls visit(face, first, second, count) once per distinct face of the tets: `face` its sorted
// corners, `first` and `second` the first two tets holding it (second is first when count is 1),
// `count` how many hold it. Faces are grouped in an open-addressing hash table, linear in the
// number of tets (sorting the faces was the most expensive step of improvement). A slot names its
// face by the first tet and the corner opposite, with a fingerprint of the face's hash, in 16
// bytes: storing the corners took 40, and the table of a Delaunay partition no longer fitted in
// cache. On the FinFET's Delaunay run, finding constrained faces and the locator's neighbours
// went from 8.4% to 4.6% of the CPU time (its TetGen calls the yardstick). The visiting order
// follows the table: callers that need an order sort what they keep.
template <typename Index, typename Visit>
void forEachDistinctFace(const Index* tetCorners, std::size_t tetCount, Visit&& visit)
{
  struct Slot
  {
    std::uint32_t first;
    std::uint32_t second;
    std::uint32_t count = 0; // 0: empty
    std::uint32_t tag;       // the corner of `first` opposite the face, and a fingerprint above it
  };
  std::size_t capacity = 16;
  // More slots than a tet soup's 4 faces per tet, so a probe always ends; a mesh has about 2.
  while (capacity <= 4 * tetCount)
  {
    capacity *= 2;
  }
  std::vector<Slot> slots(capacity);
  const std::size_t mask = capacity - 1;
  for (std::size_t t = 0; t < tetCount; ++t)
  {
    for (int skip = 0; skip < 4; ++skip)
    {
      const std::array<Index, 3> face = sortedFace(tetCorners + 4 * t, skip);
      std::uint64_t h = static_cast<std::uint64_t>(face[0]) * 0x9E3779B97F4A7C15ull;
      h ^= static_cast<std::uint64_t>(face[1]) * 0xC2B2AE3D27D4EB4Full;
      h ^= static_cast<std::uint64_t>(face[2]) * 0x165667B19E3779F9ull;
      h ^= h >> 29;
      const std::uint32_t fingerprint = static_cast<std::uint32_t>(h >> 32) & ~std::uint32_t{ 3 };
      for (std::size_t at = h & mask;; at = (at + 1) & mask)
      {
        Slot& slot = slots[at];
        if (slot.count == 0)
        {
          slot = { static_cast<std::uint32_t>(t), static_cast<std::uint32_t>(t), 1,
            fingerprint | static_cast<std::uint32_t>(skip) };
          break;
        }
        if ((slot.tag & ~std::uint32_t{ 3 }) == fingerprint &&
          sortedFace(tetCorners + 4 * std::size_t{ slot.first }, static_cast<int>(slot.tag & 3)) ==
            face)
        {
          slot.second = slot.count == 1 ? static_cast<std::uint32_t>(t) : slot.second;
          ++slot.count;
          break;
        }
      }
    }
  }
  for (const Slot& slot : slots)
  {
    if (slot.count > 0)
    {
      visit(sortedFace(tetCorners + 4 * std::size_t{ slot.first }, static_cast<int>(slot.tag & 3)),
        static_cast<std::size_t>(slot.first), static_cast<std::size_t>(slot.second),
        static_cast<std::size_t>(slot.count));
    }
  }
}

} // namespace cgmesh

#endif
