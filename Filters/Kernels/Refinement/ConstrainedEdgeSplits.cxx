#include "Refinement/ConstrainedEdgeSplits.h"

#include "Core/ConstrainedFaces.h"

#include <algorithm>

namespace cgmesh
{
namespace
{

// Enough to halve an interface edge down from 2^8 times the interface length.
constexpr int MaximumTemplateRounds = 8;

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
        const Face face = sortedFace(partition.tets[t].data(), k);
        edges.emplace(EdgeKey::of(face[0], face[1]), 0);
        edges.emplace(EdgeKey::of(face[1], face[2]), 0);
        edges.emplace(EdgeKey::of(face[0], face[2]), 0);
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
    edges.emplace(EdgeKey::of(face[0], face[1]), 0);
    edges.emplace(EdgeKey::of(face[1], face[2]), 0);
    edges.emplace(EdgeKey::of(face[0], face[2]), 0);
  }
}

// The constrained faces are found once, by hashing the partition's faces; every round hands
// their marks on to the children (refinePartition()), so later rounds know the faces without
// looking again. Only the first round sees the whole partition. It leaves a core that later
// rounds cannot touch: tets it did not split and that have no corner on a constrained face (a
// later constrained edge has its ends on such corners or on new midpoints, never on a core
// corner). Later rounds refine the rest, the shell, alone; its tets then go back in their
// ancestors' places, so the result is the one of rounds over the whole partition. On the FinFET
// the rounds go through half as many tets.
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
  const std::size_t tetsBefore = partition.tets.size();
  std::vector<std::size_t> origins;
  Status status = refinePartition(partition, context, received, refinement,
    EdgeFilter{ &constrainedEdges, true }, &origins, &marks);
  if (!status.ok())
  {
    return status;
  }
  if (partition.tets.size() == tetsBefore)
  {
    appendMarkedFaces(partition, marks, boundaryFaces, regionInterfaceFaces); // nothing split
    return status;
  }

  const std::size_t count = partition.tets.size();
  std::vector<char> inShell(count, 0);
  PartitionMesh shell;
  ConstrainedFaceMarks shellMarks;
  std::vector<std::size_t> ancestors; // per shell tet, its tet after the first round
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
      shellMarks.push_back(marks[t]);
      ancestors.push_back(t);
    }
  }
  for (int round = 1; round < MaximumTemplateRounds; ++round)
  {
    constrainedEdges.clear();
    addEdgesOfMarkedFaces(shell, shellMarks, constrainedEdges);
    const std::size_t shellBefore = shell.tets.size();
    status = refinePartition(shell, context, received, refinement,
      EdgeFilter{ &constrainedEdges, true }, &origins, &shellMarks);
    if (!status.ok())
    {
      return status;
    }
    if (shell.tets.size() == shellBefore)
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
