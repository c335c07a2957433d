// Box partitions of the improvement sweeps: every tet in one box (or left in its partition) in
// the order a serial pass gives, whatever the schedule; the way back to the partitions of the
// input cells in that order too, the first partition whole for one destination taken over as it
// is; and a box graph holding every pair of boxes that share a point, rows sorted and symmetric,
// the same under a backward schedule.
#include "CubeGenerator.h"
#include "Partitioning/BoxPartitions.h"
#include "Partitioning/HilbertPartitioner.h"
#include "Partitioning/PartitionGraph.h"
#include "ScheduleForTests.h"
#include "TestHarness.h"

#include <algorithm>
#include <cmath>
#include <vector>

using namespace cgmesh;

namespace
{

// A Kuhn cube with its interior points moved off the grid, cut into Hilbert partitions.
std::vector<PartitionMesh> jitteredCubePartitions(int n, int partitions, TetMesh& mesh)
{
  generateKuhnCube(n, mesh);
  const double h = 1.0 / n;
  for (std::size_t i = 0; i < mesh.coordinates.size(); ++i)
  {
    const double x = mesh.coordinates[i];
    if (x > 0.5 * h && x < 1 - 0.5 * h)
    {
      mesh.coordinates[i] += 0.3 * h * std::sin(12.9898 * static_cast<double>(i));
    }
  }
  std::vector<int> partitionOf;
  partitionAlongHilbertCurve(mesh, partitions, partitionOf);
  std::vector<PartitionMesh> parts(partitions);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
  {
    parts[partitionOf[t]].tets.push_back(mesh.tets[t]);
    parts[partitionOf[t]].parentCells.push_back(static_cast<CellId>(t));
    parts[partitionOf[t]].regions.push_back(static_cast<int>(t % 3));
  }
  return parts;
}

void test_box_regrouping_keeps_every_tet_in_serial_order()
{
  TetMesh mesh;
  const std::vector<PartitionMesh> partitions = jitteredCubePartitions(10, 37, mesh);
  std::vector<char> flagged(mesh.numberOfPoints(), 0);
  for (std::size_t p = 0; p < flagged.size(); p += 7)
  {
    flagged[p] = 1;
  }
  for (double shift : { 0.0, 0.5 })
  {
    const BoxLayout layout = layBoxes(mesh.coordinates, 3, shift);
    CHECK_EQUAL(layout.numberOfBoxes(), std::size_t{ 64 });
    // What a serial pass gives: partitions in order, tets in order; the tets touching no flagged
    // point stay in their partition, in order but for those past its new end, which fill the
    // places of the moving ones, in order.
    std::vector<PartitionMesh> expectedBoxes(layout.numberOfBoxes());
    std::vector<PartitionMesh> expectedStaying(partitions.size());
    for (std::size_t p = 0; p < partitions.size(); ++p)
    {
      std::vector<std::size_t> stays;
      for (std::size_t t = 0; t < partitions[p].tets.size(); ++t)
      {
        const Tet& tet = partitions[p].tets[t];
        if (touchesFlaggedPoint(tet, flagged))
        {
          appendTetOf(partitions[p], t, expectedBoxes[layout.boxOf(tet, mesh.coordinates)]);
        }
        else
        {
          stays.push_back(t);
        }
      }
      const std::size_t kept = stays.size();
      std::vector<std::size_t> fromPastEnd;
      for (std::size_t t : stays)
      {
        if (t >= kept)
        {
          fromPastEnd.push_back(t);
        }
      }
      std::size_t next = 0;
      for (std::size_t t = 0; t < kept; ++t)
      {
        const bool stayed = std::binary_search(stays.begin(), stays.end(), t);
        appendTetOf(partitions[p], stayed ? t : fromPastEnd[next++], expectedStaying[p]);
      }
      CHECK_EQUAL(next, fromPastEnd.size());
    }
    for (const ParallelFor& parallelFor : { ParallelFor(runSerially), ParallelFor(runBackwards) })
    {
      std::vector<PartitionMesh> staying = partitions, boxes;
      CHECK(regroupIntoBoxes(staying, mesh.coordinates, layout, parallelFor, boxes, &flagged).ok());
      CHECK_EQUAL(boxes.size(), expectedBoxes.size());
      for (std::size_t b = 0; b < std::min(boxes.size(), expectedBoxes.size()); ++b)
      {
        CHECK(boxes[b].tets == expectedBoxes[b].tets);
        CHECK(boxes[b].parentCells == expectedBoxes[b].parentCells);
        CHECK(boxes[b].regions == expectedBoxes[b].regions);
      }
      for (std::size_t p = 0; p < partitions.size(); ++p)
      {
        CHECK(staying[p].tets == expectedStaying[p].tets);
        CHECK(staying[p].parentCells == expectedStaying[p].parentCells);
        CHECK(staying[p].regions == expectedStaying[p].regions);
      }
      // Without flags every tet goes to a box and the partitions are emptied.
      std::vector<PartitionMesh> emptied = partitions, allBoxes;
      CHECK(regroupIntoBoxes(emptied, mesh.coordinates, layout, parallelFor, allBoxes).ok());
      std::size_t total = 0;
      for (const PartitionMesh& box : allBoxes)
      {
        total += box.tets.size();
      }
      CHECK_EQUAL(total, mesh.tets.size());
      CHECK(std::all_of(emptied.begin(), emptied.end(),
        [](const PartitionMesh& partition) { return partition.tets.empty(); }));
    }
  }
}

// The way back from boxes: every tet to the partition of its input cell, for any schedule. The
// first source whose tets all go to one partition becomes it as it is (as the partitions a sweep
// left do), and the other tets follow in the order a serial pass appends them. 24^3 * 6 tets in
// 29 boxes make more than one range of tets, and ranges that start inside a box and run across
// several; three whole sources are added, two of them for one partition.
void test_regrouping_by_cell_partition_keeps_serial_order()
{
  TetMesh mesh;
  std::vector<PartitionMesh> sources = jitteredCubePartitions(24, 29, mesh);
  const int partitions = 13;
  std::vector<int> partitionOfCell(mesh.tets.size());
  for (std::size_t t = 0; t < partitionOfCell.size(); ++t)
  {
    partitionOfCell[t] = static_cast<int>((t * 7919 + t / 5000) % partitions);
  }
  // Whole sources: the tets of box 0 bound for partition 4 (twice, the second a mixed source's
  // share as well) and those of box 1 bound for partition 7, each put in a source of its own.
  const auto wholeSource = [&](std::size_t box, int to)
  {
    PartitionMesh whole;
    for (std::size_t t = 0; t < sources[box].tets.size(); ++t)
    {
      if (partitionOfCell[sources[box].parentCells[t]] == to)
      {
        appendTetOf(sources[box], t, whole);
      }
    }
    return whole;
  };
  sources.insert(sources.begin() + 3, wholeSource(0, 4));
  sources.push_back(wholeSource(1, 7));
  sources.push_back(wholeSource(0, 4));
  std::vector<PartitionMesh> expected(partitions);
  std::vector<char> taken(partitions, 0);
  std::vector<char> takenWhole(sources.size(), 0);
  for (std::size_t s = 0; s < sources.size(); ++s)
  {
    const int to = partitionOfCell[sources[s].parentCells.front()];
    const bool whole = std::all_of(sources[s].parentCells.begin(), sources[s].parentCells.end(),
      [&](CellId parent) { return partitionOfCell[parent] == to; });
    if (whole && !taken[to])
    {
      taken[to] = 1;
      takenWhole[s] = 1;
      expected[to] = sources[s];
    }
  }
  CHECK_EQUAL(std::count(takenWhole.begin(), takenWhole.end(), 1), 2);
  for (std::size_t s = 0; s < sources.size(); ++s)
  {
    for (std::size_t t = 0; t < sources[s].tets.size() && !takenWhole[s]; ++t)
    {
      appendTetOf(sources[s], t, expected[partitionOfCell[sources[s].parentCells[t]]]);
    }
  }
  for (const ParallelFor& parallelFor : { ParallelFor(runSerially), ParallelFor(runBackwards) })
  {
    std::vector<PartitionMesh> from = sources, regrouped;
    CHECK(regroupByCellPartition(from, partitionOfCell, partitions, parallelFor, regrouped).ok());
    CHECK_EQUAL(regrouped.size(), expected.size());
    for (std::size_t p = 0; p < std::min(regrouped.size(), expected.size()); ++p)
    {
      CHECK(regrouped[p].tets == expected[p].tets);
      CHECK(regrouped[p].parentCells == expected[p].parentCells);
      CHECK(regrouped[p].regions == expected[p].regions);
    }
    CHECK(std::all_of(from.begin(), from.end(),
      [](const PartitionMesh& partition) { return partition.tets.empty(); }));
  }
}

// Every pair of boxes sharing a point is an edge of the box graph; rows sorted and symmetric.
void checkHoldsExactGraph(
  const std::vector<PartitionMesh>& boxes, const TetMesh& mesh, const PartitionGraph& graph)
{
  TetList tets;
  std::vector<int> boxOf;
  for (std::size_t b = 0; b < boxes.size(); ++b)
  {
    tets.insert(tets.end(), boxes[b].tets.begin(), boxes[b].tets.end());
    boxOf.insert(boxOf.end(), boxes[b].tets.size(), static_cast<int>(b));
  }
  PartitionGraph exact;
  CHECK(buildPartitionGraph(
    tets, boxOf, static_cast<int>(boxes.size()), mesh.numberOfPoints(), runSerially, exact)
          .ok());
  CHECK_EQUAL(graph.numberOfPartitions, exact.numberOfPartitions);
  for (int b = 0; b < std::min(graph.numberOfPartitions, exact.numberOfPartitions); ++b)
  {
    const int* row = graph.neighboursOf(b);
    CHECK(std::is_sorted(row, row + graph.degree(b)));
    for (int k = 0; k < exact.degree(b); ++k)
    {
      CHECK(std::binary_search(row, row + graph.degree(b), exact.neighboursOf(b)[k]));
    }
    for (int k = 0; k < graph.degree(b); ++k)
    {
      const int other = row[k];
      CHECK(other != b);
      CHECK(std::binary_search(
        graph.neighboursOf(other), graph.neighboursOf(other) + graph.degree(other), b));
    }
  }
}

void test_box_graph_holds_every_shared_point()
{
  TetMesh mesh;
  // 4 boxes per axis over a 12-cube: tets reach into the next box only.
  std::vector<PartitionMesh> partitions = jitteredCubePartitions(12, 10, mesh), boxes;
  const BoxLayout fine = layBoxes(mesh.coordinates, 4, 0.5);
  CHECK(regroupIntoBoxes(partitions, mesh.coordinates, fine, runSerially, boxes).ok());
  PartitionGraph graph, backwards;
  CHECK(buildBoxGraph(boxes, mesh.coordinates, fine, runSerially, graph).ok());
  CHECK(buildBoxGraph(boxes, mesh.coordinates, fine, runBackwards, backwards).ok());
  CHECK(graph.offsets == backwards.offsets && graph.neighbours == backwards.neighbours);
  CHECK(graph.numberOfEdges() > 0);
  checkHoldsExactGraph(boxes, mesh, graph);

  // 30 boxes per axis over a 2-cube: tets reach over many boxes, and the exact graph is used.
  TetMesh coarse;
  std::vector<PartitionMesh> coarseParts = jitteredCubePartitions(2, 3, coarse), coarseBoxes;
  const BoxLayout dense = layBoxes(coarse.coordinates, 30, 0.0);
  CHECK(regroupIntoBoxes(coarseParts, coarse.coordinates, dense, runSerially, coarseBoxes).ok());
  PartitionGraph coarseGraph;
  CHECK(buildBoxGraph(coarseBoxes, coarse.coordinates, dense, runSerially, coarseGraph).ok());
  checkHoldsExactGraph(coarseBoxes, coarse, coarseGraph);
}

} // namespace

int main()
{
  test_box_regrouping_keeps_every_tet_in_serial_order();
  test_regrouping_by_cell_partition_keeps_serial_order();
  test_box_graph_holds_every_shared_point();
  return cgmesh_test::finish("TestBoxPartitions");
}
