// Measures the properties every output mesh must have: conformity, orientation, no degenerate,
// duplicate or unused points, conserved volume and boundary area. Used by the tests and by the
// CLI's `check` command.
#ifndef cgmesh_MeshValidation_h
#define cgmesh_MeshValidation_h

#include "Core/TetMesh.h"

#include <cstdint>
#include <map>
#include <string>

namespace cgmesh
{

struct MeshReport
{
  CellId numberOfTets = 0;
  PointId numberOfPoints = 0;
  CellId invertedTets = 0;   // negative signed volume
  CellId degenerateTets = 0; // |volume| tiny relative to the tet's longest edge cubed
  std::int64_t boundaryFaces = 0;
  std::int64_t interiorFaces = 0;
  std::int64_t overSharedFaces = 0;      // a face in 3 or more tets
  std::int64_t misorientedFacePairs = 0; // two tets on the same side of their shared face
  std::int64_t regionInterfaceFaces = 0; // interior faces between different regions
  PointId unusedPoints = 0;
  PointId duplicatePoints = 0;   // points with bit-identical coordinates to another point
  PointId nonFinitePoints = 0;   // points with a NaN or infinite coordinate
  CellId repeatedCornerTets = 0; // a tet that names one point twice
  double volume = 0;
  double boundaryArea = 0;
  double regionInterfaceArea = 0;
  std::map<int, double> regionVolumes;

  // True when the mesh is a valid conforming tetrahedral mesh (it says nothing about conservation).
  bool isValid() const;
  // One line per violated property, empty when valid.
  std::string describeProblems() const;
};

MeshReport inspectMesh(const TetMesh& mesh);

} // namespace cgmesh

#endif
