// Every colouring is proper on random, complete, edgeless and real partition graphs; the parallel
// ones give the same colours for any thread count and schedule; the balanced ones are better
// balanced than first-fit greedy.
#include "Coloring/ColoringSupport.h"
#include "Coloring/PartitionColoring.h"
#include "CubeGenerator.h"
#include "FinFetGenerator.h"
#include "ParallelFor.h"
#include "Partitioning/MeshPartitioner.h"
#include "Partitioning/PartitionGraph.h"
#include "TestHarness.h"

#include <algorithm>
#include <random>
#include <stdexcept>

using namespace cgmesh;

namespace
{

ParallelFor threadedExecutor(int threads)
{
  return [threads](std::int64_t count, const std::function<void(std::int64_t)>& body)
  {
    return runParallel(threads, count, body);
  };
}

// Runs the tasks serially from last to first: a schedule no thread team would pick by default.
ParallelFor reversedExecutor()
{
  return [](std::int64_t count, const std::function<void(std::int64_t)>& body)
  {
    for (std::int64_t i = count - 1; i >= 0; --i)
    {
      body(i);
    }
    return Status::success();
  };
}

PartitionGraph randomGraph(int vertices, int edges, unsigned seed)
{
  std::mt19937 random(seed);
  std::vector<std::pair<int, int>> list;
  for (int e = 0; e < edges; ++e)
  {
    list.emplace_back(static_cast<int>(random() % vertices), static_cast<int>(random() % vertices));
  }
  return makePartitionGraph(vertices, list);
}

PartitionGraph completeGraph(int vertices)
{
  std::vector<std::pair<int, int>> list;
  for (int a = 0; a < vertices; ++a)
  {
    for (int b = a + 1; b < vertices; ++b)
    {
      list.emplace_back(a, b);
    }
  }
  return makePartitionGraph(vertices, list);
}

PartitionGraph meshPartitionGraph(int cubeCells, int partitions)
{
  TetMesh mesh;
  CHECK(generateKuhnCube(cubeCells, mesh).ok());
  std::vector<int> partitionOfCell;
  CHECK(partitionMesh(mesh, partitions, partitionOfCell).ok());
  PartitionGraph graph;
  CHECK(buildPartitionGraph(
    mesh.tets, partitionOfCell, partitions, mesh.numberOfPoints(), runSerially, graph)
          .ok());
  return graph;
}

double balance(const std::vector<int>& colors)
{
  const int count = countColors(colors);
  const auto sizes = colorSizes(colors, count);
  const double mean = static_cast<double>(colors.size()) / count;
  return static_cast<double>(*std::max_element(sizes.begin(), sizes.end())) / mean;
}

std::vector<int> colorWith(
  const std::string& name, const PartitionGraph& graph, const ParallelFor& executor)
{
  std::vector<int> colors;
  const auto coloring = makeColoring(name);
  CHECK(coloring != nullptr);
  CHECK(coloring->color(graph, executor, colors).ok());
  CHECK(isProperColoring(graph, colors));
  return colors;
}

void test_all_colorings_are_proper_and_deterministic()
{
  const std::vector<PartitionGraph> graphs = { randomGraph(500, 3000, 1),
    randomGraph(2000, 40000, 2), completeGraph(40), meshPartitionGraph(12, 128),
    makePartitionGraph(1, {}), makePartitionGraph(50, {}) };
  CHECK_EQUAL(coloringNames().size(), 4u);
  for (const std::string& name : coloringNames())
  {
    for (const PartitionGraph& graph : graphs)
    {
      const std::vector<int> reference = colorWith(name, graph, threadedExecutor(1));
      CHECK(colorWith(name, graph, threadedExecutor(2)) == reference);
      CHECK(colorWith(name, graph, threadedExecutor(4)) == reference);
      CHECK(colorWith(name, graph, reversedExecutor()) == reference);
    }
  }
}

void test_edge_cases()
{
  for (const std::string& name : coloringNames())
  {
    CHECK_EQUAL(countColors(colorWith(name, makePartitionGraph(1, {}), threadedExecutor(2))), 1);
    CHECK_EQUAL(countColors(colorWith(name, makePartitionGraph(50, {}), threadedExecutor(2))), 1);
    CHECK_EQUAL(countColors(colorWith(name, completeGraph(40), threadedExecutor(2))), 40);
  }
  CHECK(makeColoring("no-such-colouring") == nullptr);
}

void test_balanced_colorings_beat_greedy()
{
  const PartitionGraph graph = meshPartitionGraph(20, 512);
  const double greedy = balance(colorWith("greedy", graph, threadedExecutor(2)));
  const double leastUsed = balance(colorWith("greedy-lu", graph, threadedExecutor(2)));
  const double recolored = balance(colorWith("recoloring", graph, threadedExecutor(2)));
  std::cout << "balance (largest colour / mean): greedy " << greedy << ", greedy-lu " << leastUsed
            << ", recoloring " << recolored << "\n";
  CHECK(leastUsed < 0.8 * greedy);
  CHECK(recolored < 0.8 * greedy);
}

// A task that throws inside a colouring's parallel round is reported as that task's failure, not
// as an improper colouring found afterwards.
void test_failing_parallel_task_is_reported_as_such()
{
  const PartitionGraph graph = randomGraph(500, 3000, 3);
  const ParallelFor failing = [](std::int64_t count, const std::function<void(std::int64_t)>&)
  {
    return runParallel(2, count, [](std::int64_t) { throw std::runtime_error("task broke"); });
  };
  for (const char* name : { "iterative", "recoloring" })
  {
    std::vector<int> colors;
    const Status status = makeColoring(name)->color(graph, failing, colors);
    CHECK(!status.ok());
    CHECK(status.kind() == ErrorKind::TaskFailed);
    CHECK_EQUAL(status.message(), std::string("task broke"));
  }
}

} // namespace

// The graph by its definition: two partitions are adjacent when some point lies in tets of both;
// `interfacePoints` counts the points that do.
std::vector<std::pair<int, int>> adjacentPairsByDefinition(
  const TetMesh& mesh, const std::vector<int>& partitionOfCell, std::int64_t& interfacePoints)
{
  std::vector<std::vector<int>> partitionsOfPoint(mesh.numberOfPoints());
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
  {
    for (PointId p : mesh.tets[t])
    {
      partitionsOfPoint[p].push_back(partitionOfCell[t]);
    }
  }
  std::vector<std::pair<int, int>> pairs;
  interfacePoints = 0;
  for (std::vector<int>& partitions : partitionsOfPoint)
  {
    std::sort(partitions.begin(), partitions.end());
    partitions.erase(std::unique(partitions.begin(), partitions.end()), partitions.end());
    interfacePoints += partitions.size() > 1;
    for (int a : partitions)
    {
      for (int b : partitions)
      {
        if (a != b)
        {
          pairs.emplace_back(a, b);
        }
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

// The partition graph sorts its memberships on the given runner: for any schedule it must be the
// graph of the definition, from tets with a partition each and from partition meshes. The FinFET's
// partitions are unstructured and many of its points lie in four or more.
void test_partition_graph_is_exact_for_any_schedule()
{
  TetMesh mesh;
  CHECK(generateFinFet(30000, mesh).ok());
  const int partitions = 64;
  std::vector<int> partitionOfCell;
  CHECK(partitionMesh(mesh, partitions, partitionOfCell).ok());
  // Tets of one partition spread through the array, so the scan meets each point's partitions
  // apart and the sort does the merging: interleave the mesh's order.
  TetList tets(mesh.tets.size());
  std::vector<int> partitionOfTet(mesh.tets.size());
  for (std::size_t t = 0; t < tets.size(); ++t)
  {
    const std::size_t from = (t * 7919) % tets.size();
    tets[t] = mesh.tets[from];
    partitionOfTet[t] = partitionOfCell[from];
  }
  std::vector<PartitionMesh> meshes(partitions);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
  {
    meshes[partitionOfCell[t]].tets.push_back(mesh.tets[t]);
  }
  std::int64_t interfacePoints = 0;
  const auto expected = adjacentPairsByDefinition(mesh, partitionOfCell, interfacePoints);
  CHECK(!expected.empty());
  for (const ParallelFor& executor :
    { ParallelFor(runSerially), threadedExecutor(2), threadedExecutor(4), reversedExecutor() })
  {
    PartitionGraph fromTets, fromMeshes;
    CHECK(buildPartitionGraph(
      tets, partitionOfTet, partitions, mesh.numberOfPoints(), executor, fromTets)
            .ok());
    CHECK(buildPartitionGraph(meshes, mesh.numberOfPoints(), executor, fromMeshes).ok());
    for (const PartitionGraph* graph : { &fromTets, &fromMeshes })
    {
      std::vector<std::pair<int, int>> pairs;
      for (int a = 0; a < graph->numberOfPartitions; ++a)
      {
        CHECK(std::is_sorted(graph->neighboursOf(a), graph->neighboursOf(a) + graph->degree(a)));
        for (int k = 0; k < graph->degree(a); ++k)
        {
          pairs.emplace_back(a, graph->neighboursOf(a)[k]);
        }
      }
      CHECK(pairs == expected);
      CHECK_EQUAL(graph->interfacePoints, interfacePoints);
    }
  }
}

int main()
{
  test_failing_parallel_task_is_reported_as_such();
  test_all_colorings_are_proper_and_deterministic();
  test_edge_cases();
  test_partition_graph_is_exact_for_any_schedule();
  test_balanced_colorings_beat_greedy();
  return cgmesh_test::finish("TestColorings");
}
