#include "Refinement/ConstrainedEdgeSplits.h"

#include "Core/ConstrainedFaces.h"

#include <algorithm>

namespace cgmesh
{
namespace
{

// Enough to halve an interface edge down from 2^8 times the interface length.
constexpr int MaximumTemplateRounds = 8;

void addEdgesOf(const Face& face, EdgeSet& edges)
{
  edges.emplace(EdgeKey::of(face[0], face[1]), 0);
  edges.emplace(EdgeKey::of(face[1], face[2]), 0);
  edges.emplace(EdgeKey::of(face[0], face[2]), 0);
}

// The edges of the faces the marks name.
void addEdgesOfMarkedFaces(
  const PartitionMesh& partition, const ConstrainedFaceMarks& marks, EdgeSet& edges)
{
  for (std::size_t t = 0; t < marks.size(); ++t)
  {
    const int faces = marks[t] | (marks[t] >> InterfaceMarkShift);
    for (int k = 0; faces != 0 && k < 4; ++k)
    {
      if ((faces >> k) & 1)
      {
        addEdgesOf(sortedFace(partition.tets[t].data(), k), edges);
      }
    }
  }
}

} // namespace

void addFaceEdges(const std::vector<Face>& faces, EdgeSet& edges)
{
  edges.reserve(edges.size() + 3 * faces.size() / 2); // a closed surface: 3/2 edges per face
  for (const Face& face : faces)
  {
    addEdgesOf(face, edges);
  }
}

// The constrained faces are found once, by hashing the partition's faces; every round hands
// their marks on to the children (refinePartition()), so later rounds know the faces without
// looking again. The rounds see only the shell: the tets with a corner on a constrained face. The
// others, the core, can hold no constrained edge in any round (its ends lie on such corners or on
// new midpoints), so they are never split; on the FinFET the shell is half the partition. The
// shell's tets then go back in their ancestors' places, which makes the result, and the order in
// which midpoints are made, those of rounds over the whole partition.
Status splitConstrainedEdges(PartitionMesh& partition, const RefinementContext& context,
  const PostedSplits& received, PartitionRefinement& refinement, std::vector<Face>& boundaryFaces,
  std::vector<Face>& regionInterfaceFaces)
{
  ConstrainedFaceMarks marks;
  markConstrainedFaces(partition, marks);
  EdgeSet constrainedEdges;
  addEdgesOfMarkedFaces(partition, marks, constrainedEdges);
  PointIdSet constrainedCorners;
  constrainedCorners.reserve(constrainedEdges.size() / 2);
  constrainedEdges.forEach(
    [&](const EdgeKey& edge, char)
    {
      constrainedCorners.emplace(edge.low, 0);
      constrainedCorners.emplace(edge.high, 0);
    });

  const std::size_t count = partition.tets.size();
  std::vector<char> inShell(count, 0);
  PartitionMesh shell;
  ConstrainedFaceMarks shellMarks;
  std::vector<std::size_t> ancestors; // per shell tet, its tet in the partition
  for (std::size_t t = 0; t < count; ++t)
  {
    const Tet& tet = partition.tets[t];
    inShell[t] = std::any_of(
      tet.begin(), tet.end(), [&](PointId p) { return constrainedCorners.contains(p); });
    if (inShell[t])
    {
      appendTetOf(partition, t, shell);
      shellMarks.push_back(marks[t]);
      ancestors.push_back(t);
    }
  }
  const std::size_t shellBefore = shell.tets.size();
  std::vector<std::size_t> origins;
  for (int round = 0; round < MaximumTemplateRounds; ++round)
  {
    if (round > 0)
    {
      constrainedEdges.clear();
      addEdgesOfMarkedFaces(shell, shellMarks, constrainedEdges);
    }
    const std::size_t tetsBefore = shell.tets.size();
    Status status = refinePartition(shell, context, received, refinement,
      EdgeFilter{ &constrainedEdges, true }, &origins, &shellMarks);
    if (!status.ok())
    {
      return status;
    }
    if (shell.tets.size() == tetsBefore)
    {
      break;
    }
    for (std::size_t& origin : origins)
    {
      origin = ancestors[origin];
    }
    ancestors.swap(origins);
  }
  // The core has no constrained face: each has its corners on constrained faces.
  appendMarkedFaces(shell, shellMarks, boundaryFaces, regionInterfaceFaces);
  if (shell.tets.size() == shellBefore)
  {
    return Status::success(); // nothing split
  }
  PartitionMesh merged;
  const std::size_t mergedCount = count - shellBefore + shell.tets.size();
  merged.tets.reserve(mergedCount);
  merged.parentCells.reserve(mergedCount);
  merged.regions.reserve(partition.regions.empty() ? 0 : mergedCount);
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
