// The process that forks TetGen workers: workers are its children, never the host's; kills reach
// only its own workers; its end leaves no worker behind; the worker count is capped; workers hold
// none of the host's descriptors.
#include "TestHarness.h"
#include "WorkerSpawner.h"

#include <cerrno>
#include <cstdint>
#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>
#include <vector>

using namespace cgmesh;

namespace
{

// Descriptors the host opens before the spawner starts; a worker reports whether it holds them.
int hostPipe[2] = { -1, -1 };

// Whether the host pipe's descriptor number names a pipe here (the number alone could have been
// reused for the worker's own socket).
bool holdsHostPipe()
{
  struct stat status;
  return hostPipe[1] >= 0 && ::fstat(hostPipe[1], &status) == 0 && S_ISFIFO(status.st_mode);
}

// Answers its own and its parent's process ids and whether the host's pipe is open here, then
// waits for end of input.
[[noreturn]] void reportingWorker(int socket)
{
  const std::int32_t report[3] = { static_cast<std::int32_t>(::getpid()),
    static_cast<std::int32_t>(::getppid()), holdsHostPipe() ? 1 : 0 };
  (void)!::write(socket, report, sizeof(report));
  char byte = 0;
  while (::read(socket, &byte, 1) > 0)
  {
  }
  _exit(0);
}

// Ignores end of input: only a kill ends it.
[[noreturn]] void stubbornWorker(int)
{
  for (;;)
  {
    ::pause();
  }
}

bool readReport(int socket, std::int32_t (&report)[3])
{
  std::size_t done = 0;
  while (done < sizeof(report))
  {
    const ssize_t got =
      ::read(socket, reinterpret_cast<char*>(report) + done, sizeof(report) - done);
    if (got <= 0)
    {
      return false;
    }
    done += static_cast<std::size_t>(got);
  }
  return true;
}

// True when the peer has closed its end (the worker is gone), waiting at most `seconds`.
bool peerGone(int socket, int seconds = 10)
{
  pollfd watch{ socket, POLLIN, 0 };
  if (::poll(&watch, 1, seconds * 1000) <= 0)
  {
    return false;
  }
  char byte = 0;
  return ::recv(socket, &byte, 1, MSG_DONTWAIT) == 0;
}

void test_workers_are_children_of_the_spawner_from_any_thread()
{
  CHECK(::pipe(hostPipe) == 0); // not close-on-exec: a forked child would inherit it
  {
    WorkerSpawner spawner(reportingWorker, 4);
    std::vector<int> sockets(4, -1);
    std::vector<pid_t> processes(4, -1);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
    {
      threads.emplace_back([&, t] { CHECK(spawner.spawn(sockets[t], processes[t])); });
    }
    for (std::thread& thread : threads)
    {
      thread.join();
    }
    pid_t spawnerProcess = -1;
    for (int t = 0; t < 4; ++t)
    {
      std::int32_t report[3] = { 0, 0, 0 };
      CHECK(sockets[t] >= 0 && readReport(sockets[t], report));
      CHECK_EQUAL(report[0], static_cast<std::int32_t>(processes[t]));
      CHECK(report[1] != static_cast<std::int32_t>(::getpid())); // not forked by the host
      CHECK(t == 0 || report[1] == spawnerProcess);              // all by the one spawner
      spawnerProcess = report[1];
      CHECK_EQUAL(report[2], 0); // the host's pipe is not held open by the worker
      CHECK(::fcntl(sockets[t], F_GETFD) & FD_CLOEXEC);
    }
    for (int socket : sockets)
    {
      ::close(socket);
    }
  }
  // No process but the host holds the pipe's write end: closing it gives end of input.
  ::close(hostPipe[1]);
  hostPipe[1] = -1;
  char byte = 0;
  CHECK_EQUAL(::read(hostPipe[0], &byte, 1), 0);
  ::close(hostPipe[0]);
}

void test_kill_reaches_only_its_own_workers()
{
  WorkerSpawner spawner(stubbornWorker, 2);
  int socket = -1;
  pid_t process = -1;
  CHECK(spawner.spawn(socket, process));
  spawner.kill(::getpid()); // not its worker: ignored (the test would die otherwise)
  spawner.kill(process + 100000);
  CHECK(!peerGone(socket, 1));
  spawner.kill(process);
  CHECK(peerGone(socket, 0)); // reaped before kill() returned
  spawner.kill(process);      // a second time: already gone, ignored
  ::close(socket);
}

void test_the_spawner_caps_and_ends_its_workers()
{
  std::vector<int> sockets(3, -1);
  {
    WorkerSpawner spawner(stubbornWorker, 2);
    pid_t processes[3] = { -1, -1, -1 };
    CHECK(spawner.spawn(sockets[0], processes[0]));
    CHECK(spawner.spawn(sockets[1], processes[1]));
    CHECK(!spawner.spawn(sockets[2], processes[2])); // over the cap
    spawner.kill(processes[0]);
    ::close(sockets[0]);
    CHECK(spawner.spawn(sockets[0], processes[0])); // a slot is free again
    CHECK(!peerGone(sockets[0], 0) && !peerGone(sockets[1], 0));
  }
  // The spawner's end killed the stubborn workers, which ignore end of input.
  CHECK(peerGone(sockets[0], 0));
  CHECK(peerGone(sockets[1], 0));
  ::close(sockets[0]);
  ::close(sockets[1]);
}

} // namespace

int main()
{
  test_workers_are_children_of_the_spawner_from_any_thread();
  test_kill_reaches_only_its_own_workers();
  test_the_spawner_caps_and_ends_its_workers();
  return cgmesh_test::finish("TestWorkerSpawner");
}
