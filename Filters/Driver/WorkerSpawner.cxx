#include "WorkerSpawner.h"

#include "SocketTransfer.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace cgmesh
{
namespace
{

enum RequestKind : std::int32_t
{
  Spawn = 1, // reply: the worker's process id, with the host's socket end attached (-1: none)
  Kill = 2   // reply: the worker's wait status once it is reaped (-1: not one of its workers)
};

struct Request
{
  std::int32_t kind = 0;
  std::int32_t process = 0;
};

// A four-byte value with, when `descriptor` >= 0, that descriptor passed along (SCM_RIGHTS).
bool sendValue(int channel, std::int32_t value, int descriptor)
{
  msghdr message{};
  iovec part{ &value, sizeof(value) };
  message.msg_iov = &part;
  message.msg_iovlen = 1;
  alignas(cmsghdr) char control[CMSG_SPACE(sizeof(int))] = {};
  if (descriptor >= 0)
  {
    message.msg_control = control;
    message.msg_controllen = sizeof(control);
    cmsghdr* header = CMSG_FIRSTHDR(&message);
    header->cmsg_level = SOL_SOCKET;
    header->cmsg_type = SCM_RIGHTS;
    header->cmsg_len = CMSG_LEN(sizeof(int));
    std::memcpy(CMSG_DATA(header), &descriptor, sizeof(int));
  }
  ssize_t sent = 0;
  do
  {
    sent = ::sendmsg(channel, &message, MSG_NOSIGNAL);
  } while (sent < 0 && errno == EINTR);
  if (sent <= 0)
  {
    return false;
  }
  return sendAll(channel, reinterpret_cast<char*>(&value) + sent,
    sizeof(value) - static_cast<std::size_t>(sent));
}

// Receives sendValue's message; `descriptor` is -1 when none came. Received descriptors are
// close-on-exec.
bool receiveValue(int channel, std::int32_t& value, int& descriptor)
{
  descriptor = -1;
  msghdr message{};
  iovec part{ &value, sizeof(value) };
  message.msg_iov = &part;
  message.msg_iovlen = 1;
  alignas(cmsghdr) char control[CMSG_SPACE(sizeof(int))] = {};
  message.msg_control = control;
  message.msg_controllen = sizeof(control);
  ssize_t received = 0;
  do
  {
    received = ::recvmsg(channel, &message, MSG_CMSG_CLOEXEC);
  } while (received < 0 && errno == EINTR);
  for (cmsghdr* header = CMSG_FIRSTHDR(&message); header; header = CMSG_NXTHDR(&message, header))
  {
    if (header->cmsg_level == SOL_SOCKET && header->cmsg_type == SCM_RIGHTS)
    {
      std::memcpy(&descriptor, CMSG_DATA(header), sizeof(int));
    }
  }
  if (received <= 0 ||
    !receiveAll(channel, reinterpret_cast<char*>(&value) + received,
      sizeof(value) - static_cast<std::size_t>(received)))
  {
    if (descriptor >= 0)
    {
      ::close(descriptor);
      descriptor = -1;
    }
    return false;
  }
  return true;
}

// The spawner's bookkeeping: the workers it forked whose end the host has not yet been told, in a
// fixed array allocated by the host before the fork (the spawner itself calls no allocator). A
// worker that left by itself is reaped at once and its slot keeps its wait status until the host
// asks (kill), so the host learns how it ended and a reused process id is never signalled.
struct WorkerSlot
{
  pid_t process;
  int status;
  bool ended;
};

struct Workers
{
  WorkerSlot* slot;
  int capacity;
  int count = 0;

  int find(pid_t worker) const
  {
    for (int i = 0; i < this->count; ++i)
    {
      if (this->slot[i].process == worker)
      {
        return i;
      }
    }
    return -1;
  }
  void add(pid_t worker) { this->slot[this->count++] = WorkerSlot{ worker, 0, false }; }
  void reapFinished()
  {
    int status = 0;
    pid_t gone = 0;
    while ((gone = ::waitpid(-1, &status, WNOHANG)) > 0)
    {
      const int index = this->find(gone);
      if (index >= 0)
      {
        this->slot[index].status = status;
        this->slot[index].ended = true;
      }
    }
  }
  // Ends the worker in slot `index` if it still runs, frees the slot and returns its wait status.
  int release(int index)
  {
    WorkerSlot& worker = this->slot[index];
    if (!worker.ended)
    {
      ::kill(worker.process, SIGKILL);
      while (::waitpid(worker.process, &worker.status, 0) < 0 && errno == EINTR)
      {
      }
    }
    const int status = worker.status;
    worker = this->slot[--this->count];
    return status;
  }
};

// Keeps only the standard descriptors and the request channel, which it returns: the spawner and
// its workers hold none of the host's files or connections open, and write nothing to the user's
// terminal (TetGen's assertion messages go with failures the host reports itself).
int keepOnlyChannel(int channel)
{
  const int kept = ::fcntl(channel, F_DUPFD, 3); // above the standard descriptors
  if (kept < 0)
  {
    _exit(1);
  }
  ::close(channel);
  const int devnull = ::open("/dev/null", O_WRONLY);
  if (devnull >= 0)
  {
    ::dup2(devnull, STDERR_FILENO);
    ::close(devnull);
  }
  if (kept > 3)
  {
    ::close_range(3, static_cast<unsigned>(kept) - 1, 0);
  }
  ::close_range(static_cast<unsigned>(kept) + 1, ~0u, 0);
  return kept;
}

// A worker that crashes or aborts inside TetGen simply dies: the host sees the death and reports
// it. Handlers the host installed for these signals (a crash reporter, a sanitizer's or fuzzer's
// report writer) would otherwise run in the worker and report the host as crashed, and a core file
// per TetGen abort would only fill the disk.
void restoreDeadlySignals()
{
  const rlimit noCore = { 0, 0 };
  ::setrlimit(RLIMIT_CORE, &noCore);
  struct sigaction defaultAction = {};
  defaultAction.sa_handler = SIG_DFL;
  for (int signal : { SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL })
  {
    ::sigaction(signal, &defaultAction, nullptr);
  }
}

[[noreturn]] void serveSpawnRequests(
  int channel, WorkerSpawner::WorkerMain workerMain, Workers live)
{
  channel = keepOnlyChannel(channel);
  // Reaping needs the default disposition: with SIGCHLD ignored (inherited from a host that
  // ignores it) children vanish unreaped and a kept id could name another process.
  struct sigaction defaultAction = {};
  defaultAction.sa_handler = SIG_DFL;
  ::sigaction(SIGCHLD, &defaultAction, nullptr);

  Request request;
  while (receiveAll(channel, &request, sizeof(request)))
  {
    live.reapFinished();
    bool answered = false;
    if (request.kind == Spawn)
    {
      int ends[2] = { -1, -1 };
      pid_t worker = -1;
      if (live.count < live.capacity && ::socketpair(AF_UNIX, SOCK_STREAM, 0, ends) == 0)
      {
        worker = ::fork();
        if (worker == 0)
        {
          ::close(channel);
          ::close(ends[0]);
          restoreDeadlySignals();
          workerMain(ends[1]);
          _exit(1);
        }
        ::close(ends[1]);
      }
      if (worker > 0)
      {
        live.add(worker);
        answered = sendValue(channel, worker, ends[0]);
      }
      else
      {
        answered = sendValue(channel, -1, -1);
      }
      if (ends[0] >= 0)
      {
        ::close(ends[0]);
      }
    }
    else if (request.kind == Kill)
    {
      const int index = live.find(request.process);
      answered = sendValue(channel, index >= 0 ? live.release(index) : -1, -1);
    }
    if (!answered)
    {
      break;
    }
  }
  // The host has gone or ended the pool: no worker outlives the spawner.
  while (live.count > 0)
  {
    live.release(live.count - 1);
  }
  _exit(0);
}

} // namespace

WorkerSpawner::WorkerSpawner(WorkerMain workerMain, int maximumWorkers)
{
  int ends[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0)
  {
    return;
  }
  std::vector<WorkerSlot> slots(static_cast<std::size_t>(std::max(maximumWorkers, 1)));
  const pid_t process = ::fork();
  if (process == 0)
  {
    ::close(ends[0]);
    serveSpawnRequests(
      ends[1], workerMain, Workers{ slots.data(), static_cast<int>(slots.size()) });
  }
  ::close(ends[1]);
  if (process < 0)
  {
    ::close(ends[0]);
    return;
  }
  this->Channel = ends[0];
  this->Process = process;
}

WorkerSpawner::~WorkerSpawner()
{
  if (this->Channel >= 0)
  {
    ::close(this->Channel);
  }
  if (this->Process > 0)
  {
    int status = 0;
    while (::waitpid(this->Process, &status, 0) < 0 && errno == EINTR)
    {
    }
  }
}

bool WorkerSpawner::spawn(int& socket, pid_t& process)
{
  std::lock_guard<std::mutex> lock(this->Requests);
  const Request request{ Spawn, 0 };
  std::int32_t worker = -1;
  int descriptor = -1;
  if (this->Channel < 0 || !sendAll(this->Channel, &request, sizeof(request)) ||
    !receiveValue(this->Channel, worker, descriptor))
  {
    return false;
  }
  if (worker <= 0 || descriptor < 0)
  {
    if (descriptor >= 0)
    {
      ::close(descriptor);
    }
    return false;
  }
  socket = descriptor;
  process = worker;
  return true;
}

int WorkerSpawner::kill(pid_t process)
{
  std::lock_guard<std::mutex> lock(this->Requests);
  const Request request{ Kill, static_cast<std::int32_t>(process) };
  std::int32_t status = -1;
  int descriptor = -1;
  if (this->Channel < 0 || !sendAll(this->Channel, &request, sizeof(request)) ||
    !receiveValue(this->Channel, status, descriptor))
  {
    return -1;
  }
  if (descriptor >= 0)
  {
    ::close(descriptor);
  }
  return status;
}

} // namespace cgmesh
