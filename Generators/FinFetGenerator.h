// A double-gate FinFET as a multi-material tetrahedral mesh on a structured, graded grid whose
// planes include every material boundary, so that material interfaces conform by construction.
// Dimensions are in nanometres: a 10 nm wide, 30 nm tall fin on buried oxide, a 20 nm gate with
// 2 nm gate oxide on both fin sides and on top, spacers and isolation oxide around.
#ifndef cgmesh_FinFetGenerator_h
#define cgmesh_FinFetGenerator_h

#include "Core/Status.h"
#include "Core/TetMesh.h"

#include <string>
#include <vector>

namespace cgmesh
{

enum FinFetMaterial
{
  Substrate = 0,
  BuriedOxide = 1,
  FinChannel = 2,
  Source = 3,
  Drain = 4,
  GateOxide = 5,
  Gate = 6,
  Spacer = 7,
  Isolation = 8
};

// Names indexed by FinFetMaterial.
std::vector<std::string> finFetMaterialNames();

// Writes the device with about `targetTets` tetrahedra (at least a few thousand) and the material
// of every tet in mesh.regions: the structured version (Kuhn tets on the graded grid).
Status generateFinFet(std::int64_t targetTets, TetMesh& mesh);

// The same device meshed by TetGen from a piecewise linear complex: the material boxes' faces
// where materials change (and the outer boundary) are facets, one region seed per box carries its
// material. Quality tets (radius-edge ratio 1.414); the volume bound is searched until the tet
// count is within 5% of `targetTets` (837,584 is the size of the reference device; a coarse
// mesh, where the fixed facets dominate, may stay up to about 10% off). Calls TetGen
// in this process: meant for command-line generation, not for a long-lived host.
Status generateFinFetWithTetGen(std::int64_t targetTets, TetMesh& mesh);

} // namespace cgmesh

#endif
