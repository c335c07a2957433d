#include "TetGenWorkers.h"

#include "Refinement/TetGenRefiner.h"
#include "SocketTransfer.h"

#define TETLIBRARY
#include <tetgen.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>
#include <sys/socket.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace cgmesh
{
namespace
{

// A message is a sequence of length-prefixed arrays.
template <typename T>
bool sendArray(int socket, const T* values, std::int64_t count)
{
  return sendAll(socket, &count, sizeof(count)) &&
    (count == 0 || sendAll(socket, values, sizeof(T) * static_cast<std::size_t>(count)));
}

template <typename T>
bool receiveArray(int socket, T*& values, std::int64_t& count)
{
  values = nullptr;
  if (!receiveAll(socket, &count, sizeof(count)) || count < 0 || count > (std::int64_t(1) << 40))
  {
    return false;
  }
  if (count == 0)
  {
    return true;
  }
  values = new T[static_cast<std::size_t>(count)];
  return receiveAll(socket, values, sizeof(T) * static_cast<std::size_t>(count));
}

// The header's last entry says what follows the tets and their attributes.
enum MeshParts : int
{
  WithFaces = 1,      // the faces and their markers (a request)
  WithNeighbours = 2, // the face neighbours of each tet (a reply to TetGen's switch n)
  WithPointSizes = 4, // one size per point (a request with TetGen's switch m)
  WithFacets = 8,     // triangular facets, their markers and the region list (a request with p)
};

// The facets of a PLC made of single triangles, flattened: what the Delaunay method sends with
// switch p. False for any other facet, which this protocol does not carry.
bool flattenTriangleFacets(const tetgenio& io, std::vector<int>& corners)
{
  corners.clear();
  for (int f = 0; f < io.numberoffacets; ++f)
  {
    const tetgenio::facet& facet = io.facetlist[f];
    if (facet.numberofpolygons != 1 || facet.numberofholes != 0 ||
      facet.polygonlist[0].numberofvertices != 3)
    {
      return false;
    }
    corners.insert(
      corners.end(), facet.polygonlist[0].vertexlist, facet.polygonlist[0].vertexlist + 3);
  }
  return true;
}

bool sendMesh(int socket, const tetgenio& io, int parts)
{
  if (io.neighborlist == nullptr)
  {
    parts &= ~WithNeighbours;
  }
  if ((parts & WithFaces) && io.pointmtrlist != nullptr && io.numberofpointmtrs == 1)
  {
    parts |= WithPointSizes;
  }
  std::vector<int> facetCorners;
  if ((parts & WithFaces) && io.numberoffacets > 0)
  {
    if (!flattenTriangleFacets(io, facetCorners))
    {
      return false;
    }
    parts |= WithFacets;
  }
  const int header[4] = { io.numberofcorners, io.numberoftetrahedronattributes, io.firstnumber,
    parts };
  return sendAll(socket, header, sizeof(header)) &&
    sendArray(socket, io.pointlist, 3 * static_cast<std::int64_t>(io.numberofpoints)) &&
    (!(parts & WithPointSizes) ||
      sendArray(socket, io.pointmtrlist, static_cast<std::int64_t>(io.numberofpoints))) &&
    sendArray(
      socket, io.tetrahedronlist, std::int64_t(io.numberofcorners) * io.numberoftetrahedra) &&
    sendArray(socket, io.tetrahedronattributelist,
      std::int64_t(io.numberoftetrahedronattributes) * io.numberoftetrahedra) &&
    (!(parts & WithFaces) ||
      (sendArray(socket, io.trifacelist, 3 * static_cast<std::int64_t>(io.numberoftrifaces)) &&
        sendArray(socket, io.trifacemarkerlist, static_cast<std::int64_t>(io.numberoftrifaces)))) &&
    (!(parts & WithFacets) ||
      (sendArray(socket, facetCorners.data(), static_cast<std::int64_t>(facetCorners.size())) &&
        sendArray(socket, io.facetmarkerlist, static_cast<std::int64_t>(io.numberoffacets)) &&
        sendArray(socket, io.regionlist, 5 * static_cast<std::int64_t>(io.numberofregions)))) &&
    (!(parts & WithNeighbours) ||
      sendArray(socket, io.neighborlist, 4 * static_cast<std::int64_t>(io.numberoftetrahedra)));
}

bool receiveMesh(int socket, tetgenio& io)
{
  int header[4];
  std::int64_t count = 0;
  if (!receiveAll(socket, header, sizeof(header)))
  {
    return false;
  }
  io.numberofcorners = header[0];
  io.numberoftetrahedronattributes = header[1];
  io.firstnumber = header[2];
  const int parts = header[3];
  if (!receiveArray(socket, io.pointlist, count))
  {
    return false;
  }
  io.numberofpoints = static_cast<int>(count / 3);
  if (parts & WithPointSizes)
  {
    if (!receiveArray(socket, io.pointmtrlist, count) || count != io.numberofpoints)
    {
      return false;
    }
    io.numberofpointmtrs = 1;
  }
  if (!receiveArray(socket, io.tetrahedronlist, count) || io.numberofcorners <= 0)
  {
    return false;
  }
  io.numberoftetrahedra = static_cast<int>(count / io.numberofcorners);
  if (!receiveArray(socket, io.tetrahedronattributelist, count))
  {
    return false;
  }
  if (parts & WithFaces)
  {
    if (!receiveArray(socket, io.trifacelist, count))
    {
      return false;
    }
    io.numberoftrifaces = static_cast<int>(count / 3);
    if (!receiveArray(socket, io.trifacemarkerlist, count))
    {
      return false;
    }
  }
  if (parts & WithFacets)
  {
    int* corners = nullptr;
    const bool facets = receiveArray(socket, corners, count) && count % 3 == 0;
    if (facets)
    {
      setTriangleFacets(io, corners, static_cast<int>(count / 3));
    }
    delete[] corners;
    if (!facets || !receiveArray(socket, io.facetmarkerlist, count) || count != io.numberoffacets ||
      !receiveArray(socket, io.regionlist, count) || count % 5 != 0)
    {
      return false;
    }
    io.numberofregions = static_cast<int>(count / 5);
  }
  if (parts & WithNeighbours)
  {
    if (!receiveArray(socket, io.neighborlist, count) ||
      count != 4 * std::int64_t(io.numberoftetrahedra))
    {
      return false;
    }
  }
  return true;
}

// A request starts with what the worker is to do with it.
enum RequestKind : std::int32_t
{
  RunTetGen = 1,
  DieAfterReading = 2 // the test hook: die as an abort inside TetGen would
};

// The worker's life: read a request, run TetGen, answer; leave on end of input.
[[noreturn]] void serveRequests(int socket)
{
  for (;;)
  {
    std::int32_t kind = 0;
    char* switches = nullptr;
    std::int64_t length = 0;
    if (!receiveAll(socket, &kind, sizeof(kind)) || !receiveArray(socket, switches, length) ||
      length == 0)
    {
      _exit(0);
    }
    tetgenio in, out;
    bool received = receiveMesh(socket, in);
    std::string failure;
    if (!received)
    {
      _exit(1);
    }
    if (kind == DieAfterReading)
    {
      std::abort(); // what a failed assertion inside TetGen does
    }
    try
    {
      tetgenbehavior behavior;
      behavior.parse_commandline(switches);
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
    delete[] switches;
    const std::int32_t ok = failure.empty() ? 1 : 0;
    const bool answered = sendAll(socket, &ok, sizeof(ok)) &&
      (ok ? sendMesh(socket, out, WithNeighbours)
          : sendArray(socket, failure.data(), static_cast<std::int64_t>(failure.size())));
    if (!answered)
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

// The partition ids listed in the test hook's variable ("3,17"), sorted; what is not a
// non-negative number is ignored.
std::vector<int> partitionsToKill()
{
  std::vector<int> partitions;
  const char* text = std::getenv(TetGenWorkerPool::KillPartitionsVariable);
  while (text && *text)
  {
    char* end = nullptr;
    const long value = std::strtol(text, &end, 10);
    if (end != text && value >= 0 && value <= INT_MAX)
    {
      partitions.push_back(static_cast<int>(value));
    }
    text = end != text ? end : text + 1;
    text += *text == ',' ? 1 : 0;
  }
  std::sort(partitions.begin(), partitions.end());
  return partitions;
}

// How a worker that broke off an exchange ended, from its wait status (-1: not known).
std::string describeWorkerEnd(int status)
{
  if (status != -1 && WIFSIGNALED(status))
  {
    const int signal = WTERMSIG(status);
    const char* name = sigabbrev_np(signal);
    const std::string which = name ? std::string("SIG") + name : "signal " + std::to_string(signal);
    switch (signal)
    {
      case SIGABRT:
        return "TetGen aborted on this partition, " + which;
      case SIGSEGV:
      case SIGBUS:
      case SIGFPE:
      case SIGILL:
        return "TetGen crashed on this partition, " + which;
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

TetGenWorkerPool::TetGenWorkerPool(int workers)
  : Workers(workerCount(workers))
  , Spawner(serveRequests, static_cast<int>(this->Workers.size())) // declared after Workers
  , KillPartitions(partitionsToKill())
{
  for (Worker& worker : this->Workers)
  {
    this->start(worker);
  }
}

TetGenWorkerPool::~TetGenWorkerPool()
{
  for (Worker& worker : this->Workers)
  {
    this->stop(worker, false); // the worker reads end of input and leaves; the spawner reaps it
  }
}

bool TetGenWorkerPool::start(Worker& worker)
{
  return this->Spawner.spawn(worker.socket, worker.process);
}

int TetGenWorkerPool::stop(Worker& worker, bool kill)
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

std::string TetGenWorkerPool::run(
  int index, const tetgenio& in, const std::string& switches, tetgenio& out, int partition)
{
  Worker& worker =
    this->Workers[static_cast<std::size_t>(std::max(index, 0)) % this->Workers.size()];
  std::lock_guard<std::mutex> turn(worker.busy);
  if (worker.socket < 0 && !this->start(worker))
  {
    return "could not start a TetGen worker process";
  }
  // TetGen can also loop forever on some inputs: a call that takes far longer than its size
  // warrants is abandoned (the limit applies to each receive).
  timeval limit;
  // A remeshed partition sends no tets: about six per point.
  const double tets = in.numberoftetrahedra > 0 ? in.numberoftetrahedra : 6.0 * in.numberofpoints;
  limit.tv_sec = static_cast<time_t>(30.0 + 0.002 * tets);
  limit.tv_usec = 0;
  ::setsockopt(worker.socket, SOL_SOCKET, SO_RCVTIMEO, &limit, sizeof(limit));
  const std::int32_t kind =
    std::binary_search(this->KillPartitions.begin(), this->KillPartitions.end(), partition)
    ? DieAfterReading
    : RunTetGen;
  std::int32_t ok = 0;
  // A receive that fails at end of input leaves errno as it was: clear it, so that a stale
  // EAGAIN from an earlier call on this thread does not pass a dead worker off as a timeout.
  errno = 0;
  const bool exchanged = sendAll(worker.socket, &kind, sizeof(kind)) &&
    sendArray(worker.socket, switches.c_str(), static_cast<std::int64_t>(switches.size() + 1)) &&
    sendMesh(worker.socket, in, WithFaces) && receiveAll(worker.socket, &ok, sizeof(ok));
  if (exchanged && ok)
  {
    if (receiveMesh(worker.socket, out))
    {
      return std::string();
    }
  }
  else if (exchanged)
  {
    char* message = nullptr;
    std::int64_t length = 0;
    if (receiveArray(worker.socket, message, length))
    {
      std::string failure(message, static_cast<std::size_t>(length));
      delete[] message;
      return failure;
    }
  }
  // The worker died (an assertion in TetGen aborts it), hung, or the exchange broke: replace it.
  const bool timedOut = errno == EAGAIN || errno == EWOULDBLOCK;
  const int status = this->stop(worker, true);
  if (timedOut)
  {
    return std::string(TetGenTimeLimitReason) + " " + std::to_string(limit.tv_sec) +
      " s on this partition and was stopped";
  }
  return "the TetGen process stopped unexpectedly (" + describeWorkerEnd(status) + ")";
}

} // namespace cgmesh
