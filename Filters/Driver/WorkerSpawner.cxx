#include "WorkerSpawner.h"

#include "SocketTransfer.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <fcntl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

namespace cgmesh
{
namespace
{

enum RequestKind : std::int32_t
{
  Spawn = 1, // reply: the worker's process id, with the host's socket end attached (-1: none)
  Kill = 2   // reply: 1 once the worker is reaped
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

// The spawner's bookkeeping: the workers it forked and has not reaped, in a fixed array allocated
// by the host before the fork (the spawner itself calls no allocator).
struct LiveWorkers
{
  pid_t* process;
  int capacity;
  int count = 0;

  void remove(int index) { this->process[index] = this->process[--this->count]; }
  int find(pid_t worker) const
  {
    for (int i = 0; i < this->count; ++i)
    {
      if (this->process[i] == worker)
      {
        return i;
      }
    }
    return -1;
  }
  // Reaps the workers that have left by themselves, without waiting.
  void reapFinished()
  {
    int status = 0;
    pid_t gone = 0;
    while ((gone = ::waitpid(-1, &status, WNOHANG)) > 0)
    {
      const int index = this->find(gone);
      if (index >= 0)
      {
        this->remove(index);
      }
    }
  }
  void killAndReap(int index)
  {
    const pid_t worker = this->process[index];
    ::kill(worker, SIGKILL);
    int status = 0;
    while (::waitpid(worker, &status, 0) < 0 && errno == EINTR)
    {
    }
    this->remove(index);
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

[[noreturn]] void serveSpawnRequests(
  int channel, WorkerSpawner::WorkerMain workerMain, LiveWorkers live)
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
          workerMain(ends[1]);
          _exit(1);
        }
        ::close(ends[1]);
      }
      if (worker > 0)
      {
        live.process[live.count++] = worker;
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
      if (index >= 0)
      {
        live.killAndReap(index);
      }
      answered = sendValue(channel, 1, -1);
    }
    if (!answered)
    {
      break;
    }
  }
  // The host has gone or ended the pool: no worker outlives the spawner.
  while (live.count > 0)
  {
    live.killAndReap(live.count - 1);
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
  std::vector<pid_t> slots(static_cast<std::size_t>(std::max(maximumWorkers, 1)));
  const pid_t process = ::fork();
  if (process == 0)
  {
    ::close(ends[0]);
    serveSpawnRequests(
      ends[1], workerMain, LiveWorkers{ slots.data(), static_cast<int>(slots.size()) });
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

void WorkerSpawner::kill(pid_t process)
{
  std::lock_guard<std::mutex> lock(this->Requests);
  const Request request{ Kill, static_cast<std::int32_t>(process) };
  std::int32_t done = 0;
  int descriptor = -1;
  if (this->Channel >= 0 && sendAll(this->Channel, &request, sizeof(request)))
  {
    receiveValue(this->Channel, done, descriptor);
  }
}

} // namespace cgmesh
