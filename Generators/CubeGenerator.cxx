#include "CubeGenerator.h"

#include "Core/Geometry.h"

#include <algorithm>
#include <string>

namespace cgmesh
{
namespace
{

// Kuhn (Freudenthal) subdivision: one tet per ordering of the three axes, walking from the
// hexahedron's lowest corner to its highest one axis step at a time. Neighbouring hexahedra cut
// their shared faces along the same diagonal, so the mesh conforms.
std::vector<std::array<int, 3>> kuhnAxisOrders()
{
  std::array<int, 3> axes = { 0, 1, 2 };
  std::vector<std::array<int, 3>> orders;
  do
  {
    orders.push_back(axes);
  } while (std::next_permutation(axes.begin(), axes.end()));
  return orders;
}

} // namespace

Status generateKuhnGrid(const GridLines& lines, TetMesh& mesh)
{
  std::array<int, 3> pointsAlong;
  for (int axis = 0; axis < 3; ++axis)
  {
    const auto& values = lines[axis];
    if (values.size() < 2 || !std::is_sorted(values.begin(), values.end()) ||
      std::adjacent_find(values.begin(), values.end()) != values.end())
    {
      return Status::failure("grid lines must be at least two strictly increasing values per axis");
    }
    pointsAlong[axis] = static_cast<int>(values.size());
  }
  auto pointIndex = [&pointsAlong](const std::array<int, 3>& ijk) -> PointId
  {
    return (static_cast<PointId>(ijk[2]) * pointsAlong[1] + ijk[1]) * pointsAlong[0] + ijk[0];
  };

  mesh = TetMesh();
  for (int k = 0; k < pointsAlong[2]; ++k)
  {
    for (int j = 0; j < pointsAlong[1]; ++j)
    {
      for (int i = 0; i < pointsAlong[0]; ++i)
      {
        mesh.coordinates.insert(mesh.coordinates.end(), { lines[0][i], lines[1][j], lines[2][k] });
      }
    }
  }
  const auto orders = kuhnAxisOrders();
  for (int k = 0; k + 1 < pointsAlong[2]; ++k)
  {
    for (int j = 0; j + 1 < pointsAlong[1]; ++j)
    {
      for (int i = 0; i + 1 < pointsAlong[0]; ++i)
      {
        for (const auto& order : orders)
        {
          std::array<int, 3> corner = { i, j, k };
          Tet tet;
          tet[0] = pointIndex(corner);
          for (int step = 0; step < 3; ++step)
          {
            ++corner[order[step]];
            tet[step + 1] = pointIndex(corner);
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

Status generateKuhnCube(int cellsPerSide, TetMesh& mesh)
{
  if (cellsPerSide < 1 || cellsPerSide > 1000)
  {
    return Status::failure(
      "cube size must be between 1 and 1000 cells per side, got " + std::to_string(cellsPerSide));
  }
  std::vector<double> unit(cellsPerSide + 1);
  for (int i = 0; i <= cellsPerSide; ++i)
  {
    unit[i] = static_cast<double>(i) / cellsPerSide;
  }
  return generateKuhnGrid({ unit, unit, unit }, mesh);
}

} // namespace cgmesh
