// Checks and repairs applied to an input mesh before refinement, so that real-world meshes (from
// Netgen, Gmsh, DOLFIN, TCAD tools) either refine to a valid mesh or are refused with a clear
// message:
//   - non-finite coordinates and zero-volume tets are refused;
//   - inverted tets are reoriented (Netgen's meshes arrive fully inverted in VTK's convention,
//     DOLFIN's about half), so the output is consistently oriented;
//   - parts that touch without sharing nodes are glued where their faces match (see
//     ContactGluing.h) and kept apart elsewhere. Glued copies become unused and are dropped
//     later, at the merge.
// Point ids keep their meaning (a glued point refers to the first of its copies), so point data
// still comes from the input by id.
#ifndef cgmesh_InputPreparation_h
#define cgmesh_InputPreparation_h

#include "Core/Status.h"
#include "Core/Tasks.h"
#include "Core/TetMesh.h"

#include <string>
#include <vector>

namespace cgmesh
{

struct InputRepairs
{
  CellId reorientedTets = 0;
  PointId gluedPoints = 0;          // copies merged into a corner of a matching face
  PointId keptApartPoints = 0;      // points left distinct from a coincident one
  PointId firstKeptApartPoint = -1; // the lowest of those, or -1
};

// Fills `prepared` from `input` (left untouched) or fails with a one-line reason. `parallelFor`
// runs the scans over tets and points; the result does not depend on it.
Status prepareInput(const TetMesh& input, TetMesh& prepared, InputRepairs& repairs,
  const ParallelFor& parallelFor = ParallelFor(runSerially));

} // namespace cgmesh

#endif
