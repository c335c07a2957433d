#include "MeshPartitioner.h"

#include <metis.h>

#include <algorithm>
#include <array>
#include <limits>
#include <string>
#include <tuple>

namespace cgmesh
{

DualGraph buildDualGraph(const TetMesh& mesh)
{
  struct FaceOfTet
  {
    std::array<PointId, 3> corners;
    CellId tet;
  };
  std::vector<FaceOfTet> faces;
  faces.reserve(4 * mesh.tets.size());
  for (CellId t = 0; t < mesh.numberOfTets(); ++t)
  {
    const Tet& tet = mesh.tets[t];
    for (int skip = 0; skip < 4; ++skip)
    {
      std::array<PointId, 3> corners;
      int n = 0;
      for (int i = 0; i < 4; ++i)
      {
        if (i != skip)
        {
          corners[n++] = tet[i];
        }
      }
      std::sort(corners.begin(), corners.end());
      faces.push_back({ corners, t });
    }
  }
  std::sort(faces.begin(),
    faces.end(),
    [](const FaceOfTet& a, const FaceOfTet& b)
    { return std::tie(a.corners, a.tet) < std::tie(b.corners, b.tet); });

  std::vector<std::pair<CellId, CellId>> adjacency;
  adjacency.reserve(faces.size());
  for (std::size_t i = 0; i + 1 < faces.size(); ++i)
  {
    if (faces[i].corners == faces[i + 1].corners && faces[i].tet != faces[i + 1].tet)
    {
      adjacency.emplace_back(faces[i].tet, faces[i + 1].tet);
      adjacency.emplace_back(faces[i + 1].tet, faces[i].tet);
    }
  }
  std::sort(adjacency.begin(), adjacency.end());
  adjacency.erase(std::unique(adjacency.begin(), adjacency.end()), adjacency.end());

  DualGraph graph;
  graph.offsets.assign(mesh.tets.size() + 1, 0);
  graph.neighbours.reserve(adjacency.size());
  for (const auto& pair : adjacency)
  {
    ++graph.offsets[pair.first + 1];
    graph.neighbours.push_back(pair.second);
  }
  for (std::size_t i = 0; i < mesh.tets.size(); ++i)
  {
    graph.offsets[i + 1] += graph.offsets[i];
  }
  return graph;
}

Status partitionMesh(const TetMesh& mesh, int numberOfPartitions, std::vector<int>& partitionOfCell)
{
  const CellId tetCount = mesh.numberOfTets();
  partitionOfCell.assign(tetCount, 0);
  if (numberOfPartitions < 1)
  {
    return Status::failure("the number of partitions must be at least 1");
  }
  if (numberOfPartitions == 1 || tetCount == 0)
  {
    return Status::success();
  }
  if (numberOfPartitions > tetCount)
  {
    return Status::failure("more partitions than tets");
  }
  const DualGraph graph = buildDualGraph(mesh);
  if (graph.neighbours.size() >= static_cast<std::size_t>(std::numeric_limits<idx_t>::max()))
  {
    return Status::failure("mesh too large for METIS' 32-bit indices");
  }

  std::vector<idx_t> offsets(graph.offsets.begin(), graph.offsets.end());
  std::vector<idx_t> neighbours(graph.neighbours.begin(), graph.neighbours.end());
  std::vector<idx_t> partition(tetCount, 0);
  idx_t vertexCount = static_cast<idx_t>(tetCount);
  idx_t constraintCount = 1;
  idx_t partCount = numberOfPartitions;
  idx_t edgeCut = 0;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_NUMBERING] = 0;
  options[METIS_OPTION_SEED] = 1;
  options[METIS_OPTION_CONTIG] = 1;

  int result = METIS_PartGraphKway(&vertexCount,
    &constraintCount,
    offsets.data(),
    neighbours.data(),
    nullptr,
    nullptr,
    nullptr,
    &partCount,
    nullptr,
    nullptr,
    options,
    &edgeCut,
    partition.data());
  if (result != METIS_OK)
  {
    // Contiguity cannot be had for a disconnected mesh; partition without it.
    options[METIS_OPTION_CONTIG] = 0;
    result = METIS_PartGraphKway(&vertexCount,
      &constraintCount,
      offsets.data(),
      neighbours.data(),
      nullptr,
      nullptr,
      nullptr,
      &partCount,
      nullptr,
      nullptr,
      options,
      &edgeCut,
      partition.data());
  }
  if (result != METIS_OK)
  {
    return Status::failure(
      "METIS failed to partition the mesh (code " + std::to_string(result) + ")");
  }
  std::copy(partition.begin(), partition.end(), partitionOfCell.begin());
  return Status::success();
}

} // namespace cgmesh
