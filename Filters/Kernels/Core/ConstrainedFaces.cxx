#include "Core/ConstrainedFaces.h"

#include "Core/FaceKey.h"

#include <algorithm>

namespace cgmesh
{

void findConstrainedFaces(const PartitionMesh& partition, std::vector<Face>& boundaryFaces,
  std::vector<Face>& regionInterfaceFaces)
{
  struct FaceOfTet
  {
    Face corners;
    std::size_t tet;
  };
  std::vector<FaceOfTet> faces;
  faces.reserve(4 * partition.tets.size());
  for (std::size_t t = 0; t < partition.tets.size(); ++t)
  {
    for (int skip = 0; skip < 4; ++skip)
    {
      faces.push_back({ sortedFace(partition.tets[t].data(), skip), t });
    }
  }
  std::sort(faces.begin(), faces.end(),
    [](const FaceOfTet& a, const FaceOfTet& b) { return a.corners < b.corners; });
  for (std::size_t i = 0; i < faces.size();)
  {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].corners == faces[i].corners)
    {
      ++j;
    }
    if (j - i == 1)
    {
      boundaryFaces.push_back(faces[i].corners);
    }
    else if (!partition.regions.empty() &&
      partition.regions[faces[i].tet] != partition.regions[faces[i + 1].tet])
    {
      regionInterfaceFaces.push_back(faces[i].corners);
    }
    i = j;
  }
}

} // namespace cgmesh
