// The face-adjacency graph of a tet mesh (tets adjacent when they share a face), which METIS
// partitions.
#ifndef cgmesh_DualGraph_h
#define cgmesh_DualGraph_h

#include "Core/Status.h"
#include "Core/Tasks.h"
#include "Core/TetMesh.h"

#include <cstdint>
#include <vector>

namespace cgmesh
{

// Compressed rows; each row ascending.
struct DualGraph
{
  std::vector<std::int64_t> offsets; // size numberOfTets + 1
  std::vector<CellId> neighbours;
  // The work each vertex stands for, which partitions balance (TetWeights); empty: 1 each.
  std::vector<std::int64_t> vertexWeights;
};

// The dual graph of `tets`. A face found in more than two tets (invalid input) links none of
// them, so the graph stays symmetric as METIS requires. Ranges of tets and of points run through
// `parallelFor`; the graph does not depend on it.
Status buildDualGraph(
  const TetList& tets, DualGraph& graph, const ParallelFor& parallelFor = ParallelFor(runSerially));

// The subgraph induced by the vertices at positions [begin, end) of `order`, renumbered by
// position - begin, with their weights; `positionOf` inverts `order`.
DualGraph subgraphOfPositions(const DualGraph& graph, const std::vector<CellId>& order,
  const std::vector<CellId>& positionOf, CellId begin, CellId end);

// The dual graph of the tets at positions [begin, end) of `order` alone, numbered by position -
// begin: what subgraphOfPositions() takes out of the whole mesh's dual graph (each row's
// neighbours in the order of their tet ids), found from those tets' own faces without the whole
// mesh's graph. No weights. Only on invalid input does it differ: a face held by three or more
// tets, two of them in the range, links those two here (the graph stays symmetric).
DualGraph dualGraphOfPositions(
  const TetList& tets, const std::vector<CellId>& order, CellId begin, CellId end);

// Vertices listed group by group, ascending within each: group g holds the positions
// [groupStart[g], groupStart[g + 1]) of `order`, and `positionOf` inverts `order`, as
// subgraphOfPositions() takes them.
struct VertexGroups
{
  std::vector<CellId> order;
  std::vector<CellId> positionOf;
  std::vector<CellId> groupStart; // one entry per group, then the vertex count
};

// The groups of `groupOf` (a group in [0, groups) per vertex), by a counting sort.
VertexGroups groupVertices(const std::vector<int>& groupOf, int groups);

} // namespace cgmesh

#endif
