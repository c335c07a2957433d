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
// leave the parallel region: the first one is reported as a failed Status after the loop. While a
// WaitingHook is set on the calling thread, that thread, once it finds no index left, calls the
// hook every WaitingHookPeriodMilliseconds until the other threads are done, instead of waiting
// silently.
Status runParallel(int threads, std::int64_t count, const std::function<void(std::int64_t)>& body);

// What the calling thread does while it waits in runParallel(): a run's progress and abort hooks
// may only be called on the thread that started it, and the other threads' tasks (TetGen in a
// worker process) can take minutes. Set for its scope on the thread that makes it, around loops
// of long tasks only (the loop it applies to hands out one index at a time); scopes nest.
class WaitingHook
{
public:
  explicit WaitingHook(std::function<void()> hook);
  ~WaitingHook();
  void operator()() const;
  WaitingHook(const WaitingHook&) = delete;
  WaitingHook& operator=(const WaitingHook&) = delete;

private:
  std::function<void()> Hook;
  const WaitingHook* Outer;
};

constexpr int WaitingHookPeriodMilliseconds = 100;

// runParallel() on `threads` threads as the runner kernels take (Core/Tasks.h).
ParallelFor parallelForOn(int threads);

} // namespace cgmesh

#endif
