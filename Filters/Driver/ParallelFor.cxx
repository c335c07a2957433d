#include "ParallelFor.h"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <string>
#include <thread>

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

namespace
{

// Runs body(i) and keeps the first exception's message.
void runTask(
  const std::function<void(std::int64_t)>& body, std::int64_t i, bool& failed, std::string& message)
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

} // namespace

Status runParallel(int threads, std::int64_t count, const std::function<void(std::int64_t)>& body,
  const std::function<void()>& whileWaiting)
{
  bool failed = false;
  std::string message;
  if (whileWaiting && threads > 1 && count > 1)
  {
    // The same dynamic schedule by hand, one index at a time, and the calling thread, once it
    // finds none left, calls `whileWaiting` until every task is done, woken at once by the last;
    // the others leave. omp_get_thread_num() would not
    // tell the calling thread inside a nested region, so its id is compared.
    const std::thread::id caller = std::this_thread::get_id();
    std::atomic<std::int64_t> next{ 0 };
    std::int64_t done = 0; // under `finishing`
    std::mutex finishing;
    std::condition_variable allDone;
#pragma omp parallel num_threads(threads)
    {
      for (std::int64_t i = next.fetch_add(1); i < count; i = next.fetch_add(1))
      {
        runTask(body, i, failed, message);
        std::lock_guard<std::mutex> lock(finishing);
        if (++done == count)
        {
          allDone.notify_all();
        }
      }
      if (std::this_thread::get_id() == caller)
      {
        std::unique_lock<std::mutex> lock(finishing);
        while (!allDone.wait_for(
          lock, std::chrono::milliseconds(WaitingPollMilliseconds), [&] { return done == count; }))
        {
          lock.unlock();
          whileWaiting();
          lock.lock();
        }
      }
    }
    return failed ? Status::failure(ErrorKind::TaskFailed, message) : Status::success();
  }
  // Indices are handed out one at a time while there are few per thread, so that long tasks
  // balance; with thousands per thread (tiny partitions, ranges of a few points), in chunks that
  // leave each thread about 64 grabs: every grab is an atomic on one counter all threads share,
  // and at 65,536 partitions the merge's three loops over them spent about 0.08 s of 2 threads
  // grabbing.
  const std::int64_t chunk = std::max<std::int64_t>(1, count / (64 * std::max(1, threads)));
#pragma omp parallel for num_threads(threads) schedule(dynamic, chunk)
  for (std::int64_t i = 0; i < count; ++i)
  {
    runTask(body, i, failed, message);
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
