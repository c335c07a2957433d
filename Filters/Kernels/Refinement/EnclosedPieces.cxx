#include "Refinement/EnclosedPieces.h"

#include "Core/FaceKey.h"
#include "Core/Geometry.h"
#include "Core/LowestRootSets.h"

#include <algorithm>

namespace cgmesh
{

std::vector<int> enclosedPieces(
  const std::vector<int>& corners, const std::vector<std::array<int, 3>>& keptFaces)
{
  const std::size_t count = corners.size() / 4;
  // The lowest tet of a piece is its root, so the numbering below does not depend on the order
  // the face table is visited in.
  LowestRootSets<std::size_t> pieces(count);
  forEachDistinctFace(corners.data(), count,
    [&](const std::array<int, 3>& face, std::size_t first, std::size_t second, std::size_t shared)
    {
      if (shared == 2 && !std::binary_search(keptFaces.begin(), keptFaces.end(), face))
      {
        pieces.join(first, second);
      }
    });
  std::vector<int> pieceOfTet(count, -1);
  int pieceCount = 0;
  for (std::size_t t = 0; t < count; ++t)
  {
    const std::size_t r = pieces.root(t);
    pieceOfTet[t] = r == t ? pieceCount++ : pieceOfTet[r];
  }
  return pieceOfTet;
}

std::vector<std::array<double, 3>> pointInsideEachPiece(const std::vector<int>& corners,
  const std::vector<int>& pieceOfTet, int pieceCount, const double* coordinates)
{
  std::vector<std::array<double, 3>> points(static_cast<std::size_t>(pieceCount));
  std::vector<double> largest(static_cast<std::size_t>(pieceCount), -1.0);
  for (std::size_t t = 0; t < pieceOfTet.size(); ++t)
  {
    const int* c = corners.data() + 4 * t;
    const double volume = signedVolume6(coordinates + 3 * c[0], coordinates + 3 * c[1],
      coordinates + 3 * c[2], coordinates + 3 * c[3]);
    const std::size_t piece = static_cast<std::size_t>(pieceOfTet[t]);
    if (volume > largest[piece])
    {
      largest[piece] = volume;
      for (int axis = 0; axis < 3; ++axis)
      {
        points[piece][axis] = 0.25 *
          (coordinates[3 * c[0] + axis] + coordinates[3 * c[1] + axis] +
            coordinates[3 * c[2] + axis] + coordinates[3 * c[3] + axis]);
      }
    }
  }
  return points;
}

} // namespace cgmesh
