#include "Core/ConstrainedFaces.h"

#include <algorithm>

namespace cgmesh
{

void findConstrainedFaces(const PartitionMesh& partition, std::vector<Face>& boundaryFaces,
  std::vector<Face>& regionInterfaceFaces)
{
  ConstrainedFaceMarks marks;
  markConstrainedFaces(partition, marks);
  appendMarkedFaces(partition, marks, boundaryFaces, regionInterfaceFaces);
}

void markConstrainedFaces(const PartitionMesh& partition, ConstrainedFaceMarks& marks)
{
  marks.assign(partition.tets.size(), 0);
  const TetList& tets = partition.tets;
  forEachDistinctFace(tets.empty() ? nullptr : tets[0].data(), tets.size(),
    [&](const Face& face, std::size_t first, std::size_t second, std::size_t count)
    {
      if (count == 1)
      {
        marks[first] |= 1 << cornerOpposite(tets[first], face);
      }
      else if (!partition.regions.empty() && partition.regions[first] != partition.regions[second])
      {
        marks[first] |= 1 << (InterfaceMarkShift + cornerOpposite(tets[first], face));
        marks[second] |= 1 << (InterfaceMarkShift + cornerOpposite(tets[second], face));
      }
    });
}

void appendMarkedFaces(const PartitionMesh& partition, const ConstrainedFaceMarks& marks,
  std::vector<Face>& boundaryFaces, std::vector<Face>& regionInterfaceFaces)
{
  const std::size_t firstBoundary = boundaryFaces.size();
  const std::size_t firstInterface = regionInterfaceFaces.size();
  for (std::size_t t = 0; t < marks.size(); ++t)
  {
    for (int k = 0; marks[t] != 0 && k < 4; ++k)
    {
      if ((marks[t] >> k) & 1)
      {
        boundaryFaces.push_back(sortedFace(partition.tets[t].data(), k));
      }
      if ((marks[t] >> (InterfaceMarkShift + k)) & 1)
      {
        regionInterfaceFaces.push_back(sortedFace(partition.tets[t].data(), k));
      }
    }
  }
  std::sort(boundaryFaces.begin() + firstBoundary, boundaryFaces.end());
  std::sort(regionInterfaceFaces.begin() + firstInterface, regionInterfaceFaces.end());
  // An interface face is marked in both its tets.
  regionInterfaceFaces.erase(
    std::unique(regionInterfaceFaces.begin() + firstInterface, regionInterfaceFaces.end()),
    regionInterfaceFaces.end());
}

} // namespace cgmesh
