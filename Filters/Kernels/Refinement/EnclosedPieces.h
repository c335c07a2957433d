// The pieces of a partition that its kept faces (boundary and material-interface faces) enclose.
// When TetGen remeshes a partition from those faces (switch p), it meshes every closed pocket they
// bound, and tells them apart only by the region list (switch A): a point inside each piece of the
// partition, with its attribute. A pocket that receives no point is a cavity that belongs to other
// partitions, and is dropped from TetGen's output.
#ifndef cgmesh_EnclosedPieces_h
#define cgmesh_EnclosedPieces_h

#include <array>
#include <vector>

namespace cgmesh
{

// For tets given by their local corners (4 per tet), the piece of each tet: two tets that share a
// face not listed in `keptFaces` (sorted corners, the list sorted) are in the same piece. Pieces
// are numbered 0, 1, ... in the order of their first tet.
std::vector<int> enclosedPieces(
  const std::vector<int>& corners, const std::vector<std::array<int, 3>>& keptFaces);

// One point strictly inside each piece: the centroid of the piece's largest tet (a sliver's
// centroid may lie within rounding of its faces). `coordinates` holds 3 values per local point.
std::vector<std::array<double, 3>> pointInsideEachPiece(const std::vector<int>& corners,
  const std::vector<int>& pieceOfTet, int pieceCount, const double* coordinates);

} // namespace cgmesh

#endif
