#include "Core/ConstrainedFaces.h"

#include "Core/FaceKey.h"

#include <algorithm>

namespace cgmesh
{

void findConstrainedFaces(const PartitionMesh& partition, std::vector<Face>& boundaryFaces,
  std::vector<Face>& regionInterfaceFaces)
{
  const std::size_t firstBoundary = boundaryFaces.size();
  const std::size_t firstInterface = regionInterfaceFaces.size();
  forEachDistinctFace(partition.tets.empty() ? nullptr : partition.tets[0].data(),
    partition.tets.size(),
    [&](const Face& face, std::size_t first, std::size_t second, std::size_t count)
    {
      if (count == 1)
      {
        boundaryFaces.push_back(face);
      }
      else if (!partition.regions.empty() && partition.regions[first] != partition.regions[second])
      {
        regionInterfaceFaces.push_back(face);
      }
    });
  // In corner order, whatever the grouping order: TetGen receives them in this order.
  std::sort(boundaryFaces.begin() + firstBoundary, boundaryFaces.end());
  std::sort(regionInterfaceFaces.begin() + firstInterface, regionInterfaceFaces.end());
}

} // namespace cgmesh
