#include "CubeGenerator.h"

#include "Geometry.h"

#include <algorithm>
#include <array>
#include <string>

namespace cgmesh
{

Status generateKuhnCube(int cellsPerSide, TetMesh& mesh)
{
  if (cellsPerSide < 1 || cellsPerSide > 1000)
  {
    return Status::failure(
      "cube size must be between 1 and 1000 cells per side, got " + std::to_string(cellsPerSide));
  }
  const int n = cellsPerSide;
  const int pointsPerSide = n + 1;
  auto pointIndex = [pointsPerSide](int i, int j, int k) -> PointId
  { return (static_cast<PointId>(k) * pointsPerSide + j) * pointsPerSide + i; };

  mesh = TetMesh();
  mesh.coordinates.reserve(3 * static_cast<size_t>(pointsPerSide) * pointsPerSide * pointsPerSide);
  for (int k = 0; k < pointsPerSide; ++k)
  {
    for (int j = 0; j < pointsPerSide; ++j)
    {
      for (int i = 0; i < pointsPerSide; ++i)
      {
        mesh.coordinates.push_back(static_cast<double>(i) / n);
        mesh.coordinates.push_back(static_cast<double>(j) / n);
        mesh.coordinates.push_back(static_cast<double>(k) / n);
      }
    }
  }

  // Kuhn (Freudenthal) subdivision: one tet per ordering of the three axes, walking from the
  // cube's lowest corner to its highest one axis step at a time.
  std::array<int, 3> axes = { 0, 1, 2 };
  std::vector<std::array<int, 3>> axisOrders;
  do
  {
    axisOrders.push_back(axes);
  } while (std::next_permutation(axes.begin(), axes.end()));

  mesh.tets.reserve(6 * static_cast<size_t>(n) * n * n);
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        for (const auto& order : axisOrders)
        {
          std::array<int, 3> corner = { i, j, k };
          Tet tet;
          tet[0] = pointIndex(corner[0], corner[1], corner[2]);
          for (int step = 0; step < 3; ++step)
          {
            ++corner[order[step]];
            tet[step + 1] = pointIndex(corner[0], corner[1], corner[2]);
          }
          if (signedVolume6(mesh, tet) < 0)
          {
            std::swap(tet[2], tet[3]);
          }
          mesh.tets.push_back(tet);
        }
      }
    }
  }
  return Status::success();
}

} // namespace cgmesh
