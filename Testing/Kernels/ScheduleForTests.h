// A ParallelFor for the kernel tests that runs the calls last to first on the calling thread: a
// result that depended on the schedule would differ from runSerially's.
#ifndef cgmesh_ScheduleForTests_h
#define cgmesh_ScheduleForTests_h

#include "Core/Status.h"

#include <cstdint>
#include <functional>

namespace cgmesh
{

inline Status runBackwards(std::int64_t count, const std::function<void(std::int64_t)>& body)
{
  for (std::int64_t i = count - 1; i >= 0; --i)
  {
    body(i);
  }
  return Status::success();
}

} // namespace cgmesh

#endif
