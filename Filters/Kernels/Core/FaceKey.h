// Face keys: the three corners of a tet face in ascending order, under which both tets sharing a
// face find it (dual graph, constrained faces, TetGen output validation).
#ifndef cgmesh_FaceKey_h
#define cgmesh_FaceKey_h

#include "Core/TetMesh.h"

#include <algorithm>
#include <array>

namespace cgmesh
{

using Face = std::array<PointId, 3>; // corners in ascending order

// The corners of the face opposite corner `skip`, in ascending order: the key under which both
// tets sharing a face find it.
template <typename Index>
std::array<Index, 3> sortedFace(const Index* corners, int skip)
{
  std::array<Index, 3> face;
  int n = 0;
  for (int i = 0; i < 4; ++i)
  {
    if (i != skip)
    {
      face[n++] = corners[i];
    }
  }
  std::sort(face.begin(), face.end());
  return face;
}

} // namespace cgmesh

#endif
