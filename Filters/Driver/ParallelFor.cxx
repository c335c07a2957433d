#include "ParallelFor.h"

#include <omp.h>

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
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1)
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
