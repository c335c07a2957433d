#include "Refinement/ConstrainedEdgeSplits.h"

#include "Core/ConstrainedFaces.h"

#include <algorithm>

namespace cgmesh
{
namespace
{

// Enough to halve an interface edge down from 2^8 times the interface length.
constexpr int MaximumTemplateRounds = 8;

// Vertices of the faces, in a set.
PointIdSet cornersOf(const std::vector<Face>& faces, const std::vector<Face>& moreFaces)
{
  PointIdSet corners;
  corners.reserve(3 * (faces.size() + moreFaces.size()));
  for (const auto* list : { &faces, &moreFaces })
  {
    for (const Face& face : *list)
    {
      for (PointId p : face)
      {
        corners.emplace(p, 0);
      }
    }
  }
  return corners;
}

} // namespace

void addFaceEdges(const std::vector<Face>& faces, EdgeSet& edges)
{
  edges.reserve(edges.size() + 3 * faces.size() / 2); // a closed surface: 3/2 edges per face
  for (const Face& face : faces)
  {
    edges.emplace(EdgeKey::of(face[0], face[1]), 0);
    edges.emplace(EdgeKey::of(face[1], face[2]), 0);
    edges.emplace(EdgeKey::of(face[0], face[2]), 0);
  }
}

// Only the first round sees the whole partition. It leaves a core that later rounds cannot touch:
// tets it did not split and that have no corner on a constrained face (a later constrained edge
// has its ends on such corners or on new midpoints, never on a core corner). Later rounds refine
// and search the rest, the shell, alone; its faces against the core, which count as boundary
// there, are told apart by their corners, all of which are core corners, unlike any constrained
// face's. The shell's tets then go back in their ancestors' places, so the result is the one of
// rounds over the whole partition. On the FinFET the rounds go through half as many tets.
Status splitConstrainedEdges(PartitionMesh& partition, const RefinementContext& context,
  const PostedSplits& received, PartitionRefinement& refinement, std::vector<Face>& boundaryFaces,
  std::vector<Face>& regionInterfaceFaces)
{
  findConstrainedFaces(partition, boundaryFaces, regionInterfaceFaces);
  EdgeSet constrainedEdges;
  addFaceEdges(boundaryFaces, constrainedEdges);
  addFaceEdges(regionInterfaceFaces, constrainedEdges);
  const std::size_t tetsBefore = partition.tets.size();
  std::vector<std::size_t> origins;
  Status status = refinePartition(
    partition, context, received, refinement, EdgeFilter{ &constrainedEdges, true }, &origins);
  if (!status.ok() || partition.tets.size() == tetsBefore)
  {
    return status; // nothing split: the faces found above are still the partition's
  }

  const PointIdSet constrainedCorners = cornersOf(boundaryFaces, regionInterfaceFaces);
  const std::size_t count = partition.tets.size();
  std::vector<char> inShell(count, 0);
  PartitionMesh shell;
  std::vector<std::size_t> ancestors; // per shell tet, its tet after the first round
  PointIdSet coreCorners;
  for (std::size_t t = 0; t < count; ++t)
  {
    const Tet& tet = partition.tets[t];
    const bool splitChild =
      (t > 0 && origins[t - 1] == origins[t]) || (t + 1 < count && origins[t + 1] == origins[t]);
    inShell[t] = splitChild ||
      std::any_of(
        tet.begin(), tet.end(), [&](PointId p) { return constrainedCorners.contains(p); });
    if (inShell[t])
    {
      appendTetOf(partition, t, shell);
      ancestors.push_back(t);
    }
    else
    {
      for (PointId p : tet)
      {
        coreCorners.emplace(p, 0);
      }
    }
  }
  auto findShellFaces = [&]()
  {
    boundaryFaces.clear();
    regionInterfaceFaces.clear();
    findConstrainedFaces(shell, boundaryFaces, regionInterfaceFaces);
    boundaryFaces.erase(std::remove_if(boundaryFaces.begin(), boundaryFaces.end(),
                          [&](const Face& face) { return coreCorners.contains(face[0]); }),
      boundaryFaces.end());
  };
  for (int round = 1; round < MaximumTemplateRounds; ++round)
  {
    findShellFaces();
    constrainedEdges.clear();
    addFaceEdges(boundaryFaces, constrainedEdges);
    addFaceEdges(regionInterfaceFaces, constrainedEdges);
    const std::size_t shellBefore = shell.tets.size();
    status = refinePartition(
      shell, context, received, refinement, EdgeFilter{ &constrainedEdges, true }, &origins);
    if (!status.ok())
    {
      return status;
    }
    if (shell.tets.size() == shellBefore)
    {
      break; // the faces found above are still the shell's
    }
    for (std::size_t& origin : origins)
    {
      origin = ancestors[origin];
    }
    ancestors.swap(origins);
    if (round + 1 == MaximumTemplateRounds)
    {
      findShellFaces();
    }
  }
  PartitionMesh merged;
  std::size_t next = 0;
  for (std::size_t t = 0; t < count; ++t)
  {
    if (!inShell[t])
    {
      appendTetOf(partition, t, merged);
    }
    for (; next < ancestors.size() && ancestors[next] == t; ++next)
    {
      appendTetOf(shell, next, merged);
    }
  }
  partition = std::move(merged);
  return Status::success();
}

} // namespace cgmesh
