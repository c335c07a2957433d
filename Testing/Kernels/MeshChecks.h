// The conformity and conservation checks most kernel tests make of a refined mesh.
#ifndef cgmesh_MeshChecks_h
#define cgmesh_MeshChecks_h

#include "Core/TetQuality.h"
#include "TestHarness.h"
#include "Validation/MeshValidation.h"

#include <algorithm>
#include <iostream>
#include <vector>

namespace cgmesh_test
{

// `output` is valid (conforming, no inverted, degenerate, duplicate or unused points) and keeps
// `input`'s volume, boundary area, region-interface area and every region's volume.
inline void checkValidAndConserving(const cgmesh::TetMesh& input, const cgmesh::TetMesh& output)
{
  const cgmesh::MeshReport before = cgmesh::inspectMesh(input);
  const cgmesh::MeshReport after = cgmesh::inspectMesh(output);
  if (!after.isValid())
  {
    std::cerr << after.describeProblems();
  }
  CHECK(after.isValid());
  CHECK_CLOSE(after.volume, before.volume, 1e-12);
  CHECK_CLOSE(after.boundaryArea, before.boundaryArea, 1e-12);
  CHECK_CLOSE(after.regionInterfaceArea, before.regionInterfaceArea, 1e-12);
  CHECK_EQUAL(after.regionVolumes.size(), before.regionVolumes.size());
  for (const auto& region : before.regionVolumes)
  {
    CHECK_CLOSE(after.regionVolumes.at(region.first), region.second, 1e-12);
  }
}

// The minimum dihedral angle (degrees) below which `fraction` of the tets lie, by rank.
inline double minimumDihedralPercentile(const cgmesh::TetMesh& mesh, double fraction)
{
  std::vector<double> angles;
  for (const cgmesh::Tet& t : mesh.tets)
  {
    angles.push_back(cgmesh::minimumDihedralAngle(
      mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]), mesh.point(t[3])));
  }
  std::sort(angles.begin(), angles.end());
  return angles[static_cast<std::size_t>(fraction * static_cast<double>(angles.size() - 1))];
}

} // namespace cgmesh_test

#endif
