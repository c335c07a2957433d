// Bitwise comparison of two adaptation results: the determinism checks of the kernel tests.
#ifndef cgmesh_ResultComparison_h
#define cgmesh_ResultComparison_h

#include "AdaptationDriver.h"

#include <cstring>

namespace cgmesh_test
{

// Same points (bit for bit), tets, regions, parents, partitions, colours and provenance.
inline bool identicalResults(const cgmesh::AdaptationResult& a, const cgmesh::AdaptationResult& b)
{
  return a.mesh.coordinates.size() == b.mesh.coordinates.size() &&
    std::memcmp(a.mesh.coordinates.data(), b.mesh.coordinates.data(),
      a.mesh.coordinates.size() * sizeof(double)) == 0 &&
    a.mesh.tets == b.mesh.tets && a.mesh.regions == b.mesh.regions &&
    a.parentCell == b.parentCell && a.colorOfCell == b.colorOfCell &&
    a.partitionOfCell == b.partitionOfCell && a.provenance.sources == b.provenance.sources &&
    a.provenance.weights == b.provenance.weights;
}

} // namespace cgmesh_test

#endif
