#include "ColorLoop.h"

#include "ParallelFor.h"

#include <chrono>

namespace cgmesh
{
namespace
{

double secondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::vector<std::vector<int>> partitionsByColor(
  const std::vector<int>& colorOfPartition, int colors)
{
  std::vector<std::vector<int>> members(colors);
  for (std::size_t p = 0; p < colorOfPartition.size(); ++p)
  {
    members[colorOfPartition[p]].push_back(static_cast<int>(p));
  }
  return members;
}

// Processes one colour: the parallel heal and adapt loops, then the serial numbering of the new
// points in partition order (deterministic for any thread count), then the parallel rewrite.
Status processColor(const ColorLoopSetup& setup, const std::vector<int>& members, int color,
  const RefinementContext& context, std::vector<PartitionRefinement>& refinements,
  AdaptationState& state, AdaptationResult& result)
{
  const auto& colorOf = *setup.colorOfPartition;
  const std::int64_t count = static_cast<std::int64_t>(members.size());
  std::vector<EdgeMidpointMap> received(members.size());

  auto start = std::chrono::steady_clock::now();
  Status status = runParallel(setup.threads, count,
    [&](std::int64_t i)
    {
      const int p = members[i];
      std::vector<const Outbox*> processedNeighbours;
      const int* neighbours = setup.graph->neighboursOf(p);
      for (int k = 0; k < setup.graph->degree(p); ++k)
      {
        if (colorOf[neighbours[k]] < color)
        {
          processedNeighbours.push_back(&refinements[neighbours[k]].outbox);
        }
      }
      collectReceivedSplits(processedNeighbours, received[i]);
    });
  result.seconds.heal += secondsSince(start);
  if (!status.ok())
  {
    return status;
  }

  start = std::chrono::steady_clock::now();
  std::vector<Status> outcomes(members.size(), Status::success());
  status = runParallel(setup.threads, count,
    [&](std::int64_t i)
    {
      const int p = members[i];
      outcomes[i] = refinePartition(state.partitions[p], context, received[i], refinements[p]);
      received[i] = EdgeMidpointMap();
    });
  result.seconds.adapt += secondsSince(start);
  for (const Status& outcome : outcomes)
  {
    if (!outcome.ok())
    {
      return outcome;
    }
  }
  if (!status.ok())
  {
    return status;
  }

  start = std::chrono::steady_clock::now();
  std::vector<PointId> firstId(members.size());
  for (std::size_t i = 0; i < members.size(); ++i)
  {
    PartitionRefinement& refinement = refinements[members[i]];
    firstId[i] = static_cast<PointId>(state.coordinates.size() / 3);
    state.coordinates.insert(
      state.coordinates.end(), refinement.newCoordinates.begin(), refinement.newCoordinates.end());
    state.newPointParents.insert(state.newPointParents.end(), refinement.newPointParents.begin(),
      refinement.newPointParents.end());
    result.healedSplits += refinement.healedSplits;
    result.createdSplits += refinement.createdSplits;
    refinement.newCoordinates = std::vector<double>();
    refinement.newPointParents = std::vector<EdgeKey>();
  }
  status = runParallel(setup.threads, count,
    [&](std::int64_t i)
    {
      const int p = members[i];
      finalizeNewPoints(state.partitions[p], refinements[p], firstId[i]);
    });
  result.seconds.post += secondsSince(start);
  return status;
}

} // namespace

Status runColorLoop(const ColorLoopSetup& setup, const AdaptationOptions& options,
  AdaptationState& state, AdaptationResult& result)
{
  const auto members = partitionsByColor(*setup.colorOfPartition, setup.numberOfColors);
  const int steps = setup.numberOfIterations * setup.numberOfColors;
  for (int iteration = 0; iteration < setup.numberOfIterations; ++iteration)
  {
    // Interface flags are recomputed per iteration: the last one's splits made new interface
    // points.
    const std::vector<char> interfaceVertex =
      findInterfaceVertices(state.partitions, static_cast<PointId>(state.coordinates.size() / 3));
    RefinementContext context;
    context.coordinates = &state.coordinates;
    context.interfaceVertex = &interfaceVertex;
    context.squaredThreshold = setup.squaredThreshold;
    context.templates = setup.templates;
    std::vector<PartitionRefinement> refinements(state.partitions.size());

    for (int color = 0; color < setup.numberOfColors; ++color)
    {
      if (options.abortRequested && options.abortRequested())
      {
        result.aborted = true;
        return Status::success();
      }
      Status status =
        processColor(setup, members[color], color, context, refinements, state, result);
      if (!status.ok())
      {
        return status;
      }
      if (options.progress)
      {
        const int done = iteration * setup.numberOfColors + color + 1;
        options.progress(0.1 + 0.8 * done / steps, "refining");
      }
    }
  }
  return Status::success();
}

} // namespace cgmesh
