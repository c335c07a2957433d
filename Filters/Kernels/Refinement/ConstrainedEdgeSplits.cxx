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

// The shell's tets as the rounds see them: each with its constrained-face marks, its tet in the
// partition, and whether the last round made it by splitting a tet.
struct ShellTets
{
  PartitionMesh mesh;
  ConstrainedFaceMarks marks;
  std::vector<std::size_t> ancestors;
  std::vector<char> splitLastRound;

  void append(const PartitionMesh& from, std::size_t t, char mark, std::size_t ancestor, char split)
  {
    appendTetOf(from, t, this->mesh);
    this->marks.push_back(mark);
    this->ancestors.push_back(ancestor);
    this->splitLastRound.push_back(split);
  }
};

// One round: refines the tets of `shell` the last round made by splitting (in the first round,
// all) as one partition, and puts each one's result back in its place. A tet the last round left
// whole can hold no constrained edge too long, nor any edge a neighbour split: it would have been
// split. On the FinFET's partitions a second round over the whole shell split tets into 39,000
// of its 950,000, and a third split none of 968,000. The tets a round looks at keep their order,
// so midpoints come in the order a round over the whole shell would make them. Sets `changed`
// when a tet was split. `knownEdges` are the constrained edges of the tets looked at when the
// caller has them (the first round), else they are gathered here.
Status refineShellRound(ShellTets& shell, const EdgeSet* knownEdges,
  const RefinementContext& context, const PostedSplits& received, PartitionRefinement& refinement,
  bool& changed)
{
  PartitionMesh looked;
  ConstrainedFaceMarks lookedMarks;
  for (std::size_t t = 0; t < shell.mesh.tets.size(); ++t)
  {
    if (shell.splitLastRound[t])
    {
      appendTetOf(shell.mesh, t, looked);
      lookedMarks.push_back(shell.marks[t]);
    }
  }
  EdgeSet gathered;
  if (!knownEdges)
  {
    addEdgesOfMarkedFaces(looked, lookedMarks, gathered);
  }
  const std::size_t before = looked.tets.size();
  std::vector<std::size_t> origins;
  Status status = refinePartition(looked, context, received, refinement,
    EdgeFilter{ knownEdges ? knownEdges : &gathered, true }, &origins, &lookedMarks);
  changed = status.ok() && looked.tets.size() != before;
  if (!changed)
  {
    return status;
  }
  ShellTets next;
  const std::size_t expected = shell.mesh.tets.size() - before + looked.tets.size();
  next.mesh.tets.reserve(expected);
  next.mesh.parentCells.reserve(expected);
  next.mesh.regions.reserve(shell.mesh.regions.empty() ? 0 : expected);
  std::size_t result = 0, lookedIndex = 0;
  for (std::size_t t = 0; t < shell.mesh.tets.size(); ++t)
  {
    if (!shell.splitLastRound[t])
    {
      next.append(shell.mesh, t, shell.marks[t], shell.ancestors[t], 0);
      continue;
    }
    const std::size_t first = result;
    while (result < origins.size() && origins[result] == lookedIndex)
    {
      ++result;
    }
    const char split = result - first > 1 ? 1 : 0;
    for (std::size_t i = first; i < result; ++i)
    {
      next.append(looked, i, lookedMarks[i], shell.ancestors[t], split);
    }
    ++lookedIndex;
  }
  shell = std::move(next);
  return status;
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
  ShellTets shell;
  for (std::size_t t = 0; t < count; ++t)
  {
    const Tet& tet = partition.tets[t];
    inShell[t] = std::any_of(
      tet.begin(), tet.end(), [&](PointId p) { return constrainedCorners.contains(p); });
    if (inShell[t])
    {
      shell.append(partition, t, marks[t], t, 1); // the first round looks at every shell tet
    }
  }
  const std::size_t shellBefore = shell.mesh.tets.size();
  bool changed = true;
  for (int round = 0; round < MaximumTemplateRounds && changed; ++round)
  {
    Status status = refineShellRound(
      shell, round == 0 ? &constrainedEdges : nullptr, context, received, refinement, changed);
    if (!status.ok())
    {
      return status;
    }
  }
  // The core has no constrained face: each has its corners on constrained faces.
  appendMarkedFaces(shell.mesh, shell.marks, boundaryFaces, regionInterfaceFaces);
  if (shell.mesh.tets.size() == shellBefore)
  {
    return Status::success(); // nothing split
  }
  PartitionMesh merged;
  const std::size_t mergedCount = count - shellBefore + shell.mesh.tets.size();
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
    for (; next < shell.ancestors.size() && shell.ancestors[next] == t; ++next)
    {
      appendTetOf(shell.mesh, next, merged);
    }
  }
  partition = std::move(merged);
  return Status::success();
}

} // namespace cgmesh
