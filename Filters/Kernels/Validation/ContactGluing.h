// Assemblies of parts that touch: glue where the contact conforms, keep apart where it does not.
//
// Two boundary faces (faces of one tet only) of different tets whose corners coincide pairwise
// within a tolerance, with their tets on opposite sides, are the two copies of one face: their
// corners are merged. No other point is merged, even when it coincides with another: parts whose
// touching surfaces are meshed independently (contact meshes) stay as separate as they came, and
// each is refined on its own. Merging every coincident point instead would join such parts at
// isolated pinch vertices while leaving their faces unglued: neither one mesh nor two.
#ifndef cgmesh_ContactGluing_h
#define cgmesh_ContactGluing_h

#include "Core/Status.h"
#include "Core/Tasks.h"
#include "Core/TetMesh.h"

namespace cgmesh
{

struct ContactGluing
{
  double tolerance = 0;        // distance under which two points coincide
  PointId gluedPoints = 0;     // used points merged into the lowest id of their glued copies
  PointId keptApartPoints = 0; // used points left distinct from a coincident, lower one
  PointId firstKeptApart = -1; // the lowest of those, or -1
};

// Points coincide within 1e-10 times the diagonal of the used points' bounding box: far below any
// edge of a mesh worth refining, far above the rounding of coordinates written as text.
constexpr double RelativeContactTolerance = 1e-10;

// Rewrites `mesh.tets` so that glued copies refer to the lowest id among them; coordinates and
// point ids are untouched (the dropped copies become unused). The result does not depend on the
// order in which faces or points are visited, nor on `parallelFor`, which runs the search for
// coincident points. `used` lists the points the tets use, ascending (listUsedPoints()).
Status glueMatchingFaces(TetMesh& mesh, const std::vector<PointId>& used,
  const ParallelFor& parallelFor, ContactGluing& outcome);

} // namespace cgmesh

#endif
