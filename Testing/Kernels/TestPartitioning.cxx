// METIS partitioning, flat and hierarchical: every tet in a partition, every partition used, the
// same result for any schedule of the second level, and without contiguity as with it.
#include "CubeGenerator.h"
#include "Partitioning/MeshPartitioner.h"
#include "TestHarness.h"

#include <algorithm>
#include <vector>

using namespace cgmesh;

namespace
{

// Runs the calls from last to first: a schedule no thread team would pick by default.
Status runReversed(std::int64_t count, const std::function<void(std::int64_t)>& body)
{
  for (std::int64_t i = count - 1; i >= 0; --i)
  {
    body(i);
  }
  return Status::success();
}

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
    std::vector<int> serial, reversed, loose;
    CHECK(partitionMesh(mesh, partitions, serial, options).ok());
    checkCovers(serial, partitions);
    options.parallelFor = runReversed;
    CHECK(partitionMesh(mesh, partitions, reversed, options).ok());
    CHECK(serial == reversed);
    options.contiguous = false;
    CHECK(partitionMesh(mesh, partitions, loose, options).ok());
    checkCovers(loose, partitions);
  }
}

void test_failing_second_level_is_reported()
{
  TetMesh mesh;
  CHECK(generateKuhnCube(8, mesh).ok());
  PartitioningOptions options;
  options.hierarchicalFrom = 100;
  options.parallelFor = [](std::int64_t, const std::function<void(std::int64_t)>&)
  {
    return Status::failure(ErrorKind::TaskFailed, "task broke");
  };
  std::vector<int> partitionOfCell;
  const Status status = partitionMesh(mesh, 400, partitionOfCell, options);
  CHECK(status.kind() == ErrorKind::TaskFailed);
}

} // namespace

int main()
{
  test_flat_and_hierarchical();
  test_failing_second_level_is_reported();
  return cgmesh_test::finish("TestPartitioning");
}
