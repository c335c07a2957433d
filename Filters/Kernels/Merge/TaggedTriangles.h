// Triangles tagged on faces of the input tets, as FEM and TCAD meshes carry boundary conditions,
// contacts and material interfaces, followed through refinement: every output face that lies in a
// tagged triangle becomes one of its children, so the tags cover the same surface afterwards.
//
// Only faces that refinement keeps as faces can carry tags: the domain boundary and the faces
// between two regions. Improvement and the Delaunay method never move or cross those, and their
// vertices keep exact provenance (a boundary vertex is never relocated), which is what the
// matching below relies on.
#ifndef cgmesh_TaggedTriangles_h
#define cgmesh_TaggedTriangles_h

#include "Core/TetMesh.h"
#include "Merge/MeshMerge.h"

#include <array>
#include <cstddef>
#include <limits>
#include <vector>

namespace cgmesh
{

using Triangle = std::array<PointId, 3>; // three point ids, in the input's order

struct TaggedTriangleCheck
{
  static constexpr std::size_t None = std::numeric_limits<std::size_t>::max();
  std::size_t notFaces = 0;        // triangles that are no face of any tet
  std::size_t firstNotFace = None; // index of the first of them
  std::size_t insideRegion = 0;    // faces shared by two tets of one region (or of no regions)
  std::size_t firstInsideRegion = None;
  bool ok() const { return notFaces == 0 && insideRegion == 0; }
};

// Which triangles are no face of `mesh`'s tets (repeated corners included), and which are faces
// inside one region, where improvement and Delaunay refinement are free to remove them.
TaggedTriangleCheck checkTaggedTriangles(
  const TetMesh& mesh, const std::vector<Triangle>& triangles);

struct TriangleChild
{
  std::size_t parent; // index into the tagged triangles
  Triangle corners;   // output point ids, ordered so that the normal points as the parent's
};

// The children of every tagged triangle among the faces of `output`, found from the provenance of
// their corners (over input point ids): a face is a child of a triangle when the input points its
// three corners are made of are exactly the triangle's corners. Sorted by parent, then by
// corners, so the result depends only on the output mesh. `triangles` must pass
// checkTaggedTriangles on `input`.
std::vector<TriangleChild> findTriangleChildren(const TetMesh& input,
  const std::vector<Triangle>& triangles, const TetMesh& output, const PointProvenance& provenance);

// The same found by position, for an output whose boundary was triangulated anew (a sliver-laden
// input meshed anew with its tagged triangles free to split and to merge with coplanar ones of
// the same cell data): a boundary or region-interface face of `output` is a child of the tagged
// triangle that holds its centroid, in the triangle's plane and parallel to it (within rounding).
// Where the centroid lies in several (on an edge two triangles share), the one listed first is
// the parent, with any listed at the same corners. Sorted as findTriangleChildren's.
std::vector<TriangleChild> findTriangleChildrenByPosition(
  const TetMesh& input, const std::vector<Triangle>& triangles, const TetMesh& output);

} // namespace cgmesh

#endif
