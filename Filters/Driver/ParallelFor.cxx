#include "ParallelFor.h"

#include <omp.h>

#include <algorithm>
#include <exception>
#include <string>

namespace cgmesh
{

int resolveThreadCount(int requested)
{
  return requested > 0 ? requested : omp_get_max_threads();
}

int currentThreadIndex()
{
  return omp_get_thread_num();
}

Status runParallel(int threads, std::int64_t count, const std::function<void(std::int64_t)>& body)
{
  bool failed = false;
  std::string message;
  // Indices are handed out one at a time while there are few per thread, so that long tasks
  // balance; with thousands per thread (tiny partitions, ranges of a few points), in chunks that
  // leave each thread about 64 grabs: every grab is an atomic on one counter all threads share,
  // and at 65,536 partitions the merge's three loops over them spent about 0.08 s of 2 threads
  // grabbing.
  const std::int64_t chunk = std::max<std::int64_t>(1, count / (64 * std::max(1, threads)));
#pragma omp parallel for num_threads(threads) schedule(dynamic, chunk)
  for (std::int64_t i = 0; i < count; ++i)
  {
    try
    {
      body(i);
    }
    catch (const std::exception& error)
    {
#pragma omp critical(cgmesh_parallel_error)
      if (!failed)
      {
        failed = true;
        message = error.what();
      }
    }
    catch (...)
    {
#pragma omp critical(cgmesh_parallel_error)
      if (!failed)
      {
        failed = true;
        message = "unknown error in a parallel task";
      }
    }
  }
  return failed ? Status::failure(ErrorKind::TaskFailed, message) : Status::success();
}

ParallelFor parallelForOn(int threads)
{
  return [threads](std::int64_t count, const std::function<void(std::int64_t)>& body)
  {
    return runParallel(threads, count, body);
  };
}

} // namespace cgmesh
