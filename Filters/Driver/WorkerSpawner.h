// A helper process that forks worker processes on request, so that the host never forks while its
// threads run.
//
// fork() in a multithreaded process copies only the calling thread: a lock another thread held at
// that moment (in the allocator, stdio, the OpenMP runtime, the host application) stays locked in
// the child for good. The spawner is forked once, when a pool is created on the calling thread
// before any parallel loop of the run; it uses nothing but system calls from then on, and every
// worker is forked from it, a single-threaded process. A worker that dies in the middle of a
// colour is therefore replaced without an OpenMP thread ever calling fork().
#ifndef cgmesh_WorkerSpawner_h
#define cgmesh_WorkerSpawner_h

#include <mutex>
#include <sys/types.h>

namespace cgmesh
{

class WorkerSpawner
{
public:
  // What a worker runs on its end of the socket pair; it must not return.
  using WorkerMain = void (*)(int socket);

  // Forks the spawner now. At most `maximumWorkers` workers are alive at a time.
  WorkerSpawner(WorkerMain workerMain, int maximumWorkers);
  // Ends the spawner, which kills the workers still alive and reaps them all before it exits.
  ~WorkerSpawner();
  WorkerSpawner(const WorkerSpawner&) = delete;
  WorkerSpawner& operator=(const WorkerSpawner&) = delete;

  // Starts a worker. On success sets the host's end of its socket (close-on-exec) and its
  // process id; false if the spawner is gone or could not fork. Safe from any thread.
  bool spawn(int& socket, pid_t& process);

  // Kills a worker this spawner started (unless it has ended by itself), waits until it is reaped
  // and returns its wait status (waitpid's), or -1 when the process is not one of its workers or
  // the spawner is gone. Only the spawner, the workers' parent, kills: a process id the host kept
  // could already name an unrelated process once a dead worker was reaped. Safe from any thread.
  int kill(pid_t process);

private:
  int Channel = -1; // the host's end of the request socket
  pid_t Process = -1;
  std::mutex Requests; // one request and its reply at a time
};

} // namespace cgmesh

#endif
