#include "WorkerPool.h"

#include "ParallelFor.h"
#include "Partitioning/MeshPartitioner.h"
#include "Refinement/TetGenRefiner.h"
#include "SocketTransfer.h"
#include "WorkerMessages.h"

#include "Core/Geometry.h"

#define TETLIBRARY
#include <tetgen.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <climits>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <malloc.h>
#include <new>
#include <poll.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace cgmesh
{
namespace
{

// A request starts with what the worker is to do with it.
enum RequestKind : std::int32_t
{
  RunTetGen = 1,
  DieAfterReading = 2, // the test hooks: die as an abort inside TetGen would,
  PartitionGraph = 3,
  StallAfterReading = 4, // or hang without computing,
  SpinAfterReading = 5   // or compute for ever, as a looping call would
};

// A call that waits this many times its limit on the clock ends even when its worker, not
// computing (blocked, or starved of the processor by other processes), is far from its limit
// in processor time.
constexpr int WallClockLimitFactor = 10;

// The processor seconds `process` has used, or a negative number when they cannot be read.
double processorSecondsOf(pid_t process)
{
  clockid_t clock;
  timespec used;
  if (process <= 0 || ::clock_getcpuclockid(process, &clock) != 0 ||
    ::clock_gettime(clock, &used) != 0)
  {
    return -1;
  }
  return static_cast<double>(used.tv_sec) + 1e-9 * static_cast<double>(used.tv_nsec);
}

// Reads TetGen's switches and mesh, runs TetGen and answers. False when the exchange broke.
bool serveTetGen(int socket, RequestKind kind)
{
  std::vector<char> switches;
  tetgenio in, out;
  if (!receiveArray(socket, switches) || switches.empty() || switches.back() != '\0' ||
    !receiveMesh(socket, in))
  {
    return false;
  }
  if (kind == DieAfterReading)
  {
    std::abort(); // what a failed assertion inside TetGen does
  }
  while (kind == StallAfterReading)
  {
    ::pause(); // until the host kills this worker
  }
  for (volatile std::uint64_t turns = 0; kind == SpinAfterReading;)
  {
    turns = turns + 1; // until the host kills this worker
  }
  std::string failure;
  try
  {
    tetgenbehavior behavior;
    behavior.parse_commandline(switches.data());
    tetrahedralize(&behavior, &in, &out);
  }
  catch (int code)
  {
    failure = "TetGen stopped with error code " + std::to_string(code);
  }
  catch (const std::bad_alloc&)
  {
    failure = "TetGen ran out of memory";
  }
  const std::int32_t ok = failure.empty() ? 1 : 0;
  return sendAll(socket, &ok, sizeof(ok)) &&
    (ok ? sendMesh(socket, out, WithNeighbours)
        : sendArray(socket, failure.data(), static_cast<std::int64_t>(failure.size())));
}

// Reads a part count, the contiguity flag and a dual graph, runs METIS and answers with the part
// of each vertex. False when the exchange broke.
bool servePartitionGraph(int socket)
{
  std::int32_t settings[2] = { 0, 0 };
  DualGraph graph;
  if (!receiveAll(socket, settings, sizeof(settings)) || !receiveGraph(socket, graph))
  {
    return false;
  }
  std::vector<int> partOfVertex;
  std::string failure;
  try
  {
    const Status status = partitionGraphWithMetis(graph, settings[0], partOfVertex, settings[1]);
    failure = status.ok() ? std::string() : status.message();
  }
  catch (const std::bad_alloc&)
  {
    failure = "METIS ran out of memory";
  }
  const std::int32_t ok = failure.empty() ? 1 : 0;
  return sendAll(socket, &ok, sizeof(ok)) &&
    (ok ? sendArray(socket, partOfVertex.data(), static_cast<std::int64_t>(partOfVertex.size()))
        : sendArray(socket, failure.data(), static_cast<std::int64_t>(failure.size())));
}

// Allocations up to this size come from the worker's heap, which keeps up to this much freed
// memory: far more than a partition's TetGen call takes, and a bound on what a worker holds idle.
constexpr int MaximumHeldAllocation = 256 << 20;

// The worker's life: read a request, serve it; leave on end of input.
[[noreturn]] void serveRequests(int socket)
{
  // TetGen allocates and frees its pools on every call. Kept in the worker's heap (no block of
  // up to 256 MiB mapped on its own, none handed back when freed), the next call reuses those pages
  // instead of faulting fresh zeroed ones in: on the Big cube at V = 0.1 x the mean tet volume,
  // one thread, the run's page faults fell from 241,000 to 102,000 and its system time from 0.99
  // to 0.49 s. Only the worker, a process of this library's own, is tuned so; the host may be
  // ParaView's.
  mallopt(M_MMAP_THRESHOLD, MaximumHeldAllocation);
  mallopt(M_TRIM_THRESHOLD, MaximumHeldAllocation);
  for (;;)
  {
    std::int32_t kind = 0;
    if (!receiveAll(socket, &kind, sizeof(kind)))
    {
      _exit(0);
    }
    const bool served = kind == PartitionGraph
      ? servePartitionGraph(socket)
      : serveTetGen(socket, static_cast<RequestKind>(kind));
    if (!served)
    {
      _exit(1);
    }
  }
}

} // namespace

namespace
{

// More workers than cores only add processes that wait for a core.
std::size_t workerCount(int requested)
{
  const std::size_t cores = std::max(1u, std::thread::hardware_concurrency());
  return std::min(static_cast<std::size_t>(std::max(requested, 1)), cores);
}

// The numbers listed in a test hook's variable ("3,17"), sorted; what is not a non-negative
// number is ignored.
std::vector<int> numbersListedIn(const char* variable)
{
  std::vector<int> numbers;
  const char* text = std::getenv(variable);
  while (text && *text)
  {
    char* end = nullptr;
    const long value = std::strtol(text, &end, 10);
    if (end != text && value >= 0 && value <= INT_MAX)
    {
      numbers.push_back(static_cast<int>(value));
    }
    text = end != text ? end : text + 1;
    text += *text == ',' ? 1 : 0;
  }
  std::sort(numbers.begin(), numbers.end());
  return numbers;
}

// How a worker that broke off an exchange ended, from its wait status (-1: not known), for a
// message that names the `program` it ran and the `piece` of the mesh it had.
std::string describeWorkerEnd(int status, const std::string& program, const std::string& piece)
{
  if (status != -1 && WIFSIGNALED(status))
  {
    const int signal = WTERMSIG(status);
    const char* name = sigabbrev_np(signal);
    const std::string which = name ? std::string("SIG") + name : "signal " + std::to_string(signal);
    switch (signal)
    {
      case SIGABRT:
        return program + " aborted on this " + piece + ", " + which;
      case SIGSEGV:
      case SIGBUS:
      case SIGFPE:
      case SIGILL:
        return program + " crashed on this " + piece + ", " + which;
      case SIGKILL:
        return "killed by SIGKILL, as by the system when memory runs out";
      default:
        return "ended by " + which;
    }
  }
  if (status != -1 && WIFEXITED(status))
  {
    return "it exited with status " + std::to_string(WEXITSTATUS(status)) +
      " after a broken exchange";
  }
  return "its exchange with the host broke off";
}

} // namespace

double tetgenTimeLimitSeconds(const tetgenio& in, const std::string& switches)
{
  // A remeshed partition sends no tets: about six per point.
  const double tets = in.numberoftetrahedra > 0 ? in.numberoftetrahedra : 6.0 * in.numberofpoints;
  const std::size_t bound = switches.find('a');
  const double volumeBound =
    bound == std::string::npos ? 0 : std::strtod(switches.c_str() + bound + 1, nullptr);
  if (!(volumeBound > 0) || in.numberoftetrahedra <= 0 || in.numberofcorners < 4 ||
    switches.find('m') != std::string::npos)
  {
    return 30.0 + 0.002 * tets;
  }
  // 50 us per forecast output tet, ten times the most a call took on the Big cube, the FinFET,
  // the sliver-laden benchmark input, a 1000:1:1 bar and TetGen's tetrahedralisation of 4,000
  // random points (4.8 us, 2 cores of a VM): a looping call (that last input had one) costs the
  // whole limit, which was five times this.
  return std::max(2.0, 5e-5 * forecastRefinedTets(in, volumeBound));
}

WorkerPool::WorkerPool(int workers)
  : Workers(workerCount(workers))
  , Spawner(serveRequests, static_cast<int>(this->Workers.size())) // declared after Workers
  , KillPartitions(numbersListedIn(KillPartitionsVariable))
{
  const std::vector<int> stalling = numbersListedIn(StallWorkerVariable);
  this->StallWorker = stalling.empty() ? -1 : stalling.front();
  const std::vector<int> spinning = numbersListedIn(SpinWorkerVariable);
  this->SpinWorker = spinning.empty() ? -1 : spinning.front();
  const std::vector<int> seconds = numbersListedIn(TimeLimitVariable);
  this->TimeLimitSeconds = seconds.empty() ? 0 : seconds.front();
  for (Worker& worker : this->Workers)
  {
    this->start(worker);
  }
}

WorkerPool::~WorkerPool()
{
  for (Worker& worker : this->Workers)
  {
    this->stop(worker, false); // the worker reads end of input and leaves; the spawner reaps it
  }
}

bool WorkerPool::start(Worker& worker)
{
  return this->Spawner.spawn(worker.socket, worker.process);
}

int WorkerPool::stop(Worker& worker, bool kill)
{
  const int status = kill && worker.process > 0 ? this->Spawner.kill(worker.process) : -1;
  if (worker.socket >= 0)
  {
    ::close(worker.socket);
  }
  worker.socket = -1;
  worker.process = -1;
  return status;
}

std::string WorkerPool::exchange(int index, time_t seconds, const std::string& program,
  const std::string& piece, bool abortable, const std::function<bool(int)>& request,
  const std::function<bool(int)>& readResult)
{
  const bool watched = abortable && this->KeepGoing;
  if (watched && !this->KeepGoing())
  {
    return WorkerCallAbortedReason;
  }
  Worker& worker = this->Workers[this->slotOf(index)];
  // Threads beyond the workers take turns: one waiting for its turn asks the run as well, every
  // WaitingPollMilliseconds. The turn is polled with try_lock every millisecond rather than
  // waited for with a timed lock: libstdc++ 12 times std::timed_mutex with
  // pthread_mutex_clocklock, which ThreadSanitizer (LLVM 14, scripts/run-tsan) does not see, and
  // it then reports the accesses the lock orders as races.
  std::unique_lock<std::mutex> turn(worker.busy, std::try_to_lock);
  for (int polls = 1; !turn.owns_lock(); ++polls)
  {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    if (polls % WaitingPollMilliseconds == 0 && watched && !this->KeepGoing())
    {
      return WorkerCallAbortedReason;
    }
    turn.try_lock();
  }
  if (worker.socket < 0 && !this->start(worker))
  {
    return "could not start a worker process for " + program;
  }
  // The limit applies to each receive; an abortable call's wait for its reply counts the
  // worker's processor time instead (below), with this as the limit on the rest of the reply.
  timeval limit;
  limit.tv_sec = seconds;
  limit.tv_usec = 0;
  ::setsockopt(worker.socket, SOL_SOCKET, SO_RCVTIMEO, &limit, sizeof(limit));
  std::int32_t ok = 0;
  // A receive that fails at end of input leaves errno as it was: clear it, so that a stale
  // EAGAIN from an earlier call on this thread does not pass a dead worker off as a timeout.
  errno = 0;
  bool exchanged = request(worker.socket);
  bool processorTimeLimit = false;
  if (exchanged && abortable)
  {
    // The reply's first bytes are waited for in slices, the run asked between them. The limit
    // counts the processor time the worker spends on the call, which the machine's load and the
    // run's thread count barely change, where seconds on the clock stretch with both: whether a
    // slow call is stopped, and its partition meshed anew or refined by templates, decides the
    // output. A worker that hangs without computing ends at WallClockLimitFactor times the limit.
    const double processorStart = processorSecondsOf(worker.process);
    const auto start = std::chrono::steady_clock::now();
    for (;;)
    {
      pollfd reply{ worker.socket, POLLIN, 0 };
      if (::poll(&reply, 1, WaitingPollMilliseconds) != 0)
      {
        break; // readable, closed, or an error: the receive below tells which
      }
      if (watched && !this->KeepGoing())
      {
        this->stop(worker, true);
        return WorkerCallAbortedReason;
      }
      const double processorUsed = processorSecondsOf(worker.process) - processorStart;
      const bool counted = processorStart >= 0 && processorUsed >= 0;
      processorTimeLimit = counted && processorUsed > static_cast<double>(seconds);
      const auto wallLimit =
        std::chrono::seconds(counted ? WallClockLimitFactor * seconds : seconds);
      if (processorTimeLimit || std::chrono::steady_clock::now() - start > wallLimit)
      {
        errno = EAGAIN; // as the receive's own limit reports it
        exchanged = false;
        break;
      }
    }
  }
  exchanged = exchanged && receiveAll(worker.socket, &ok, sizeof(ok));
  if (exchanged && ok)
  {
    if (readResult(worker.socket))
    {
      return std::string();
    }
  }
  else if (exchanged)
  {
    std::vector<char> message;
    if (receiveArray(worker.socket, message))
    {
      return std::string(message.begin(), message.end());
    }
  }
  // The worker died (an assertion in TetGen aborts it), hung, or the exchange broke: replace it.
  const bool timedOut = errno == EAGAIN || errno == EWOULDBLOCK;
  const int status = this->stop(worker, true);
  if (timedOut)
  {
    return program + " took longer than " + std::to_string(seconds) + " s" +
      (processorTimeLimit ? " of processor time" : "") + " on this " + piece + " and was stopped";
  }
  return "the " + program + " process stopped unexpectedly (" +
    describeWorkerEnd(status, program, piece) + ")";
}

std::string WorkerPool::runTetGen(
  int index, const tetgenio& in, const std::string& switches, tetgenio& out, int partition)
{
  const bool kill =
    std::binary_search(this->KillPartitions.begin(), this->KillPartitions.end(), partition);
  const auto hooked = [&](int worker)
  {
    return worker >= 0 && this->slotOf(index) == static_cast<std::size_t>(worker);
  };
  const std::int32_t kind = kill ? DieAfterReading
    : hooked(this->StallWorker)  ? StallAfterReading
    : hooked(this->SpinWorker)   ? SpinAfterReading
                                 : RunTetGen;
  const double seconds =
    this->TimeLimitSeconds > 0 ? this->TimeLimitSeconds : tetgenTimeLimitSeconds(in, switches);
  return this->exchange(
    index, static_cast<time_t>(seconds), "TetGen", "partition", true,
    [&](int socket)
    {
      return sendAll(socket, &kind, sizeof(kind)) &&
        sendArray(socket, switches.c_str(), static_cast<std::int64_t>(switches.size() + 1)) &&
        sendMesh(socket, in, WithFaces);
    },
    [&](int socket) { return receiveMesh(socket, out); });
}

std::string WorkerPool::partitionGraph(
  int index, const DualGraph& graph, int parts, bool contiguous, std::vector<int>& partOfVertex)
{
  const std::int32_t kind = PartitionGraph;
  const std::int32_t settings[2] = { parts, contiguous ? 1 : 0 };
  const std::size_t vertices = graph.offsets.empty() ? 0 : graph.offsets.size() - 1;
  // METIS takes about half a second per million vertices; a call far beyond that is hung.
  return this->exchange(
    index, static_cast<time_t>(60.0 + 1e-4 * static_cast<double>(vertices)), "METIS", "chunk",
    false,
    [&](int socket)
    {
      return sendAll(socket, &kind, sizeof(kind)) && sendAll(socket, settings, sizeof(settings)) &&
        sendGraph(socket, graph);
    },
    [&](int socket)
    { return receiveArray(socket, partOfVertex) && partOfVertex.size() == vertices; });
}

} // namespace cgmesh
