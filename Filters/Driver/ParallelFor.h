// The project's single threading choke point: every parallel loop goes through runParallel().
#ifndef cgmesh_ParallelFor_h
#define cgmesh_ParallelFor_h

#include "Core/Status.h"
#include "Core/Tasks.h"

#include <cstdint>
#include <functional>

namespace cgmesh
{

// Threads used for a request: 0 means every available core.
int resolveThreadCount(int requested);

// Index of the calling thread within the current runParallel() team: 0 .. threads-1 (0 outside).
int currentThreadIndex();

// Calls body(i) for i in [0, count) on `threads` threads, dynamically scheduled. Exceptions never
// leave the parallel region: the first one is reported as a failed Status after the loop.
Status runParallel(int threads, std::int64_t count, const std::function<void(std::int64_t)>& body);

// runParallel() on `threads` threads as the runner kernels take (Core/Tasks.h).
ParallelFor parallelForOn(int threads);

} // namespace cgmesh

#endif
