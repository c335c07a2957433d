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
//
// With `whileWaiting`, for loops of long tasks (TetGen calls, which can take minutes): indices
// are handed out one at a time, and the calling thread, once it finds none left, calls
// `whileWaiting` every WaitingPollMilliseconds until the other threads are done, instead of
// waiting silently (a run's progress and abort hooks may only be called on that thread).
Status runParallel(int threads, std::int64_t count, const std::function<void(std::int64_t)>& body,
  const std::function<void()>& whileWaiting = nullptr);

// How often a wait on long tasks or on a worker process looks up from it.
constexpr int WaitingPollMilliseconds = 100;

// runParallel() on `threads` threads as the runner kernels take (Core/Tasks.h).
ParallelFor parallelForOn(int threads);

} // namespace cgmesh

#endif
