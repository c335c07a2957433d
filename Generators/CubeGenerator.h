// Structured test meshes: boxes cut into hexahedra along given grid lines, six Kuhn tetrahedra per
// hexahedron. All tets are positively oriented (det[p1-p0, p2-p0, p3-p0] > 0, VTK's convention).
#ifndef cgmesh_CubeGenerator_h
#define cgmesh_CubeGenerator_h

#include "Core/Status.h"
#include "Core/TetMesh.h"

#include <array>
#include <vector>

namespace cgmesh
{

// Strictly increasing coordinates of the grid planes along x, y and z.
using GridLines = std::array<std::vector<double>, 3>;

Status generateKuhnGrid(const GridLines& lines, TetMesh& mesh);

// The unit cube as N^3 hexahedra: N = 10 gives the 6,000-tet "Small" cube, N = 25 the 93,750-tet
// "Big" one.
Status generateKuhnCube(int cellsPerSide, TetMesh& mesh);

} // namespace cgmesh

#endif
