// The double-gate FinFET's geometry (nanometres), shared by its two generators: material
// boundaries are axis-aligned planes at the breakpoints below.
#ifndef cgmesh_FinFetLayout_h
#define cgmesh_FinFetLayout_h

#include <vector>

namespace cgmesh
{

// Breakpoints along x (source | spacer | gate | spacer | drain), y (isolation | gate | oxide |
// fin | oxide | gate | isolation) and z (substrate | buried oxide | fin | top oxide | gate).
const std::vector<double>& finFetBreaks(int axis);

// The material (a FinFetMaterial) at a point strictly inside one box of the breakpoint grid.
int finFetMaterialAt(double x, double y, double z);

} // namespace cgmesh

#endif
