// Structured test meshes: the unit cube cut into N^3 hexahedra of six Kuhn tetrahedra each.
#ifndef cgmesh_CubeGenerator_h
#define cgmesh_CubeGenerator_h

#include "Status.h"
#include "TetMesh.h"

namespace cgmesh
{

// N = 10 gives the 6,000-tet "Small" cube, N = 25 the 93,750-tet "Big" one. All tets are
// positively oriented (det[p1-p0, p2-p0, p3-p0] > 0, VTK's convention).
Status generateKuhnCube(int cellsPerSide, TetMesh& mesh);

} // namespace cgmesh

#endif
