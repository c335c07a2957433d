// METIS partitioning, flat and hierarchical: every tet in a partition, every partition used, the
// same result on every call, and without contiguity as with it.
#include "CubeGenerator.h"
#include "Partitioning/MeshPartitioner.h"
#include "TestHarness.h"

#include <algorithm>
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

} // namespace

int main()
{
  test_flat_and_hierarchical();
  return cgmesh_test::finish("TestPartitioning");
}
