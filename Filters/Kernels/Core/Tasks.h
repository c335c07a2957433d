// How kernels with independent pieces of work (parallel colouring rounds, hierarchical
// partitioning) run them without a threading library: the driver supplies the runner.
#ifndef cgmesh_Tasks_h
#define cgmesh_Tasks_h

#include "Core/Status.h"

#include <cstdint>
#include <functional>

namespace cgmesh
{

// Runs body(i) for every i in [0, count), possibly concurrently, and returns a failure when a call
// threw. The result must not depend on how the calls are scheduled.
using ParallelFor =
  std::function<Status(std::int64_t count, const std::function<void(std::int64_t)>& body)>;

// The runner for serial use: every call in order, on the calling thread.
inline Status runSerially(std::int64_t count, const std::function<void(std::int64_t)>& body)
{
  for (std::int64_t i = 0; i < count; ++i)
  {
    body(i);
  }
  return Status::success();
}

} // namespace cgmesh

#endif
