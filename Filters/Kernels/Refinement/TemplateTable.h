// Templates for splitting a tetrahedron at the midpoints of any subset of its six edges.
//
// Local vertex numbering: 0..3 are the tet's corners, 4 + e is the midpoint of edge e, with edges
// ordered as in TetEdgeCorners. Every face of the tet is triangulated by a rule that only looks at
// that face (so both tets sharing a face agree):
//   - no split edge: the face itself;
//   - one split edge: two triangles through the midpoint and the opposite corner;
//   - two split edges: the corner triangle they cut off, and the remaining quadrilateral split by
//     the diagonal through its lower-ranked original corner (a total order on global vertex ids);
//   - three split edges: four triangles (red refinement).
// The quadrilateral rule also excludes the cyclic prism that admits no split into three tets.
// A tet with all six edges split becomes four corner tets plus an octahedron cut along one of
// its three diagonals (the caller picks the shortest).
#ifndef cgmesh_TemplateTable_h
#define cgmesh_TemplateTable_h

#include "Core/Status.h"
#include "Core/Tasks.h"

#include <array>
#include <cstdint>
#include <vector>

namespace cgmesh
{

using LocalTet = std::array<std::uint8_t, 4>;

// The templates of split masks 1..62 as plain data, in the order the search builds them: for mask
// m and the k-th order of the corner ranks (TemplateTable::rankOrders()), the child tets
// are those at corners[4 * t] for t from offsets[(m - 1) * 24 + k] up to the next offset. The
// build writes them once (TemplateTableGenerator.cxx), so that a run need not search.
struct TemplateData
{
  static constexpr int Entries = 62 * 24;
  const std::uint32_t* offsets; // Entries + 1
  const std::uint8_t* corners;
};

// The data written at build time (CompiledTemplates.cxx).
TemplateData compiledTemplateData();

class TemplateTable
{
public:
  // Builds every template and validates each one (positive volumes summing to the parent's, faces
  // matching the rules above); status() says whether every case could be built. The searches
  // for the 24 orders of the corners are independent: `parallelFor` runs them (about 30 ms in
  // all on one thread).
  explicit TemplateTable(const ParallelFor& parallelFor = ParallelFor(runSerially));
  // Takes the templates from `data` and checks each one as the search's (positive volumes summing
  // to the parent's, every inner face seen from both sides, the rules' triangles on the surface):
  // about 2 ms on one thread.
  explicit TemplateTable(const TemplateData& data);

  const Status& status() const { return this->Validity; }

  // The child tets for one split pattern. `splitMask` has bit e set when edge e is split (1..62);
  // `cornerRanks[i]` is corner i's position (0..3) in the global vertex order.
  const std::vector<LocalTet>& partialSplit(
    int splitMask, const std::array<int, 4>& cornerRanks) const;

  // The eight child tets when all six edges are split; `diagonal` 0, 1, 2 cuts the inner
  // octahedron along the midpoints of edges (0,5), (1,4) or (2,3) respectively.
  const std::vector<LocalTet>& fullSplit(int diagonal) const;

  // The most children the split pattern gives under any order of the corners (1 for none, 8
  // for all six edges): what refining a tet with that pattern can add at most.
  int mostChildren(int splitMask) const { return this->MostChildren[splitMask]; }

  static int rankCode(const std::array<int, 4>& cornerRanks);
  // The 24 orders of the corner ranks, in std::next_permutation order from 0, 1, 2, 3.
  static std::vector<std::array<int, 4>> rankOrders();

private:
  void addFullSplits(); // and MostChildren

  std::vector<std::vector<LocalTet>> Partial; // indexed by splitMask * 256 + rankCode
  std::array<int, 64> MostChildren{};
  std::array<std::vector<LocalTet>, 3> Full;
  Status Validity = Status::success();
};

// Triangulation of one tet face under the rules above, in local vertex numbers; exposed so that
// tests can check both sides of a face agree. `face` lists three corners.
std::vector<std::array<int, 3>> triangulateFace(
  const std::array<int, 3>& face, int splitMask, const std::array<int, 4>& cornerRanks);

// Local index (0..5) of the edge joining corners a and b.
int localEdgeIndex(int a, int b);

} // namespace cgmesh

#endif
