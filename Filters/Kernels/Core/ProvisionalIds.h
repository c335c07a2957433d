// Provisional point ids. A partition numbers the vertices it creates while its colour runs
// -(k + 1) for the k-th one, since global ids are handed out only after the colour, in partition
// order (the source of determinism). These helpers are the one place that encoding lives.
#ifndef cgmesh_ProvisionalIds_h
#define cgmesh_ProvisionalIds_h

#include "Core/TetMesh.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace cgmesh
{

inline bool isProvisional(PointId id)
{
  return id < 0;
}

// The provisional id of the partition's k-th new vertex.
inline PointId provisionalId(std::size_t k)
{
  return -static_cast<PointId>(k) - 1;
}

// k for a provisional id: the index into the partition's new-vertex arrays.
inline std::size_t provisionalIndex(PointId id)
{
  return static_cast<std::size_t>(-id - 1);
}

// The global id a point gets once the partition's new vertices are numbered from `firstGlobalId`.
inline PointId finalId(PointId id, PointId firstGlobalId)
{
  return isProvisional(id) ? firstGlobalId + static_cast<PointId>(provisionalIndex(id)) : id;
}

// Coordinates of a global or provisional point.
inline const double* pointCoordinates(
  const std::vector<double>& global, const std::vector<double>& provisional, PointId id)
{
  return isProvisional(id) ? provisional.data() + 3 * provisionalIndex(id) : global.data() + 3 * id;
}

// The size-field value of a global or provisional point (sizes are kept beside coordinates).
inline double pointSize(
  const std::vector<double>& global, const std::vector<double>& provisional, PointId id)
{
  return isProvisional(id) ? provisional[provisionalIndex(id)] : global[id];
}

// The position of a vertex in the global order that decides face diagonals. Provisional ids come
// after every global id, in creation order: exactly the order of the global ids they will get,
// since ids are handed out colour by colour. So a partition and a neighbour that sees the same
// vertex with its final id rank it alike.
inline std::uint64_t vertexRank(PointId id)
{
  return isProvisional(id) ? (std::uint64_t(1) << 62) + provisionalIndex(id)
                           : static_cast<std::uint64_t>(id);
}

} // namespace cgmesh

#endif
