// What the Delaunay kernel tests share: the options of a small Delaunay run, a run that checks its
// status, and the setting for handing a whole mesh to refinePartitionDelaunay() as one partition.
#ifndef cgmesh_DelaunayTestSupport_h
#define cgmesh_DelaunayTestSupport_h

#include "AdaptationDriver.h"
#include "Refinement/TemplateTable.h"
#include "Refinement/TetGenRefiner.h"
#include "TestHarness.h"

#include <iostream>
#include <vector>

namespace cgmesh_test
{
using namespace cgmesh;

inline AdaptationOptions delaunayOptions(int threads, int iterations)
{
  AdaptationOptions options;
  options.method = RefinementMethod::Delaunay;
  options.numberOfPartitions = 64;
  options.numberOfThreads = threads;
  options.numberOfIterations = iterations;
  options.volumeFactor = 0.05;
  return options;
}

inline AdaptationResult run(const TetMesh& input, const AdaptationOptions& options)
{
  AdaptationResult result;
  const Status status = adaptMesh(input, options, result);
  CHECK(status.ok());
  if (!status.ok())
  {
    std::cerr << status.message() << "\n";
  }
  return result;
}

// What refinePartitionDelaunay() needs of a whole mesh handed over as one partition: no interface
// vertices, the templates, and the interface length of the volume bound.
struct PartitionSetting
{
  PartitionSetting(const TetMesh& mesh, const DelaunayParameters& parameters)
    : interfaceVertex(mesh.numberOfPoints(), 0)
  {
    context.coordinates = &mesh.coordinates;
    context.interfaceVertex = &this->interfaceVertex;
    context.templates = &this->templates;
    const double interfaceLength = interfaceEdgeLengthForVolume(parameters.maximumVolume);
    context.squaredThreshold = interfaceLength * interfaceLength;
  }
  PartitionSetting(const PartitionSetting&) = delete;

  const TemplateTable templates;
  const std::vector<char> interfaceVertex;
  RefinementContext context;
};

} // namespace cgmesh_test

#endif
