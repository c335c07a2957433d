// METIS partitioning, flat and hierarchical: every tet in a partition, every partition used, the
// same result on every call, and without contiguity as with it. The Hilbert curve: a path through
// every grid cell once, each step to a face neighbour; its partitions: equal runs.
#include "CubeGenerator.h"
#include "Partitioning/HilbertPartitioner.h"
#include "Partitioning/MeshPartitioner.h"
#include "TestHarness.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <vector>

using namespace cgmesh;

namespace
{

void checkCovers(const std::vector<int>& partitionOfCell, int partitions)
{
  std::vector<int> tetsOf(partitions, 0);
  for (int p : partitionOfCell)
  {
    CHECK(p >= 0 && p < partitions);
    if (p >= 0 && p < partitions)
    {
      ++tetsOf[p];
    }
  }
  CHECK(std::count(tetsOf.begin(), tetsOf.end(), 0) == 0);
  // METIS balances within a few percent; two levels keep each part near the mean too.
  const int largest = *std::max_element(tetsOf.begin(), tetsOf.end());
  CHECK(largest <= 2 * static_cast<int>(partitionOfCell.size()) / partitions + 2);
}

void test_flat_and_hierarchical()
{
  TetMesh mesh;
  CHECK(generateKuhnCube(12, mesh).ok()); // 10,368 tets
  for (int partitions : { 7, 64, 500, 2000 })
  {
    PartitioningOptions options;
    options.hierarchicalFrom = 100; // 500 and 2000 go through two levels
    std::vector<int> first, again, loose;
    CHECK(partitionMesh(mesh, partitions, first, options).ok());
    checkCovers(first, partitions);
    CHECK(partitionMesh(mesh, partitions, again, options).ok());
    CHECK(first == again);
    options.contiguous = false;
    CHECK(partitionMesh(mesh, partitions, loose, options).ok());
    checkCovers(loose, partitions);
  }
}

void test_hilbert_curve_visits_every_cell_through_faces()
{
  for (int bits = 1; bits <= 4; ++bits)
  {
    const std::uint32_t side = 1u << bits;
    std::vector<std::array<std::uint32_t, 3>> cellAt(side * side * side);
    std::vector<int> visits(cellAt.size(), 0);
    for (std::uint32_t x = 0; x < side; ++x)
    {
      for (std::uint32_t y = 0; y < side; ++y)
      {
        for (std::uint32_t z = 0; z < side; ++z)
        {
          const std::uint64_t index = hilbertIndex({ x, y, z }, bits);
          CHECK(index < cellAt.size());
          if (index < cellAt.size())
          {
            ++visits[index];
            cellAt[index] = { x, y, z };
          }
        }
      }
    }
    CHECK(std::count(visits.begin(), visits.end(), 1) == static_cast<long>(visits.size()));
    for (std::size_t i = 1; i < cellAt.size(); ++i)
    {
      int distance = 0;
      for (int axis = 0; axis < 3; ++axis)
      {
        distance +=
          std::abs(static_cast<int>(cellAt[i][axis]) - static_cast<int>(cellAt[i - 1][axis]));
      }
      CHECK_EQUAL(distance, 1);
    }
  }
}

void test_hilbert_partitions_are_equal_runs()
{
  TetMesh mesh;
  CHECK(generateKuhnCube(12, mesh).ok()); // 10,368 tets
  for (int partitions : { 1, 7, 64, 2000, 10368 })
  {
    std::vector<int> first, again;
    CHECK(partitionAlongHilbertCurve(mesh, partitions, first).ok());
    CHECK(partitionAlongHilbertCurve(mesh, partitions, again).ok());
    CHECK(first == again);
    std::vector<int> tetsOf(partitions, 0);
    for (int p : first)
    {
      CHECK(p >= 0 && p < partitions);
      ++tetsOf[std::clamp(p, 0, partitions - 1)];
    }
    const int fewest = static_cast<int>(mesh.tets.size()) / partitions;
    for (int count : tetsOf)
    {
      CHECK(count == fewest || count == fewest + 1);
    }
  }
  std::vector<int> partitionOfCell;
  CHECK(!partitionAlongHilbertCurve(mesh, 10369, partitionOfCell).ok());
  CHECK(!partitionAlongHilbertCurve(mesh, 0, partitionOfCell).ok());
}

} // namespace

int main()
{
  test_flat_and_hierarchical();
  test_hilbert_curve_visits_every_cell_through_faces();
  test_hilbert_partitions_are_equal_runs();
  return cgmesh_test::finish("TestPartitioning");
}
