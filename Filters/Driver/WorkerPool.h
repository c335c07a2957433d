// TetGen and METIS run in worker processes, one per thread.
//
// Two facts about TetGen 1.5 as packaged make in-process calls unsafe for a long-lived host such
// as pvserver: every tetrahedralize() call rewrites process-wide state (the predicates' error
// bounds and bounding-box filter, the static mesh-navigation tables), so concurrent calls race;
// and the library is built with assertions, which abort the whole process on some degenerate
// inputs (seen with -Y and a volume bound on valid partitions). A worker process has TetGen's
// globals to itself, and when it dies the call simply fails: the partition falls back to
// templates and the worker is replaced. METIS draws from the C library's process-wide random
// generator, so two calls in one process at once would make the partitions depend on timing; in
// separate processes each call's draws are its own. Workers are forked by a WorkerSpawner, never
// by the host's threads.
#ifndef cgmesh_WorkerPool_h
#define cgmesh_WorkerPool_h

#include "Partitioning/DualGraph.h"
#include "WorkerSpawner.h"

#include <algorithm>
#include <ctime>
#include <functional>
#include <mutex>
#include <string>
#include <sys/types.h>
#include <utility>
#include <vector>

class tetgenio;

namespace cgmesh
{

// How many seconds of processor time a TetGen call with `switches` on `in` may take before it
// counts as looping. With a volume bound (a) on given tets, 50 us per forecast output tet (the
// tets given plus four per volume bound of their volume), about 20 times what a call takes at
// half a million tets a second, at least 2 s; otherwise 30 s plus 2 ms per tet given.
double tetgenTimeLimitSeconds(const tetgenio& in, const std::string& switches);

class WorkerPool
{
public:
  // Starts `workers` worker processes, at most one per core, and the spawner that forks them and
  // their replacements (forked now, from the calling thread).
  explicit WorkerPool(int workers);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  // Runs TetGen with `switches` on `in` in worker `worker` modulo the number of workers (callers
  // that share a worker take turns) and fills `out`. Returns an empty string on success, else
  // why it failed. `partition` names the partition the call refines (-1: none), for the test
  // hook below.
  std::string runTetGen(
    int worker, const tetgenio& in, const std::string& switches, tetgenio& out, int partition = -1);

  // Cuts `graph` into `parts` parts with METIS (partitionGraphWithMetis) in worker `worker` modulo
  // the number of workers. The same result as the call in this process. Returns an empty string
  // on success, else why it failed.
  std::string partitionGraph(
    int worker, const DualGraph& graph, int parts, bool contiguous, std::vector<int>& partOfVertex);

  // While a TetGen call waits for its worker's turn or for the reply, `keepGoing` is asked every
  // WaitingPollMilliseconds (and once before the call) whether the run goes on; when it
  // says no, the call fails with WorkerCallAbortedReason, and a worker cut short in its call is
  // killed and replaced. Any thread calls it. METIS calls are short and run to the end.
  void setAbortCheck(std::function<bool()> keepGoing) { this->KeepGoing = std::move(keepGoing); }
  // Test hooks, read once when the pool starts. CGMESH_TEST_KILL_TETGEN_PARTITIONS, a
  // comma-separated list of partition ids: a worker that receives a call for one of them aborts
  // once it has read the request, as a failed assertion inside TetGen ends it; the host sees a
  // dead worker, the call fails and the worker is replaced. CGMESH_TEST_STALL_TETGEN_WORKER, a
  // worker index: that worker (the one thread i calls) hangs on every TetGen call instead, as a
  // looping call would, until an abort ends it (or ten times the call's time limit: a worker that
  // hangs uses no processor time). CGMESH_TEST_SPIN_TETGEN_WORKER, a worker index: that worker
  // computes for ever instead, until the call's limit on its processor time or an abort ends it.
  // CGMESH_TEST_TETGEN_SECONDS, a whole number of seconds: every TetGen call's time limit.
  static constexpr const char* KillPartitionsVariable = "CGMESH_TEST_KILL_TETGEN_PARTITIONS";
  static constexpr const char* StallWorkerVariable = "CGMESH_TEST_STALL_TETGEN_WORKER";
  static constexpr const char* SpinWorkerVariable = "CGMESH_TEST_SPIN_TETGEN_WORKER";
  static constexpr const char* TimeLimitVariable = "CGMESH_TEST_TETGEN_SECONDS";

private:
  struct Worker
  {
    pid_t process = -1;
    int socket = -1;
    std::mutex busy; // one request at a time; process and socket change only under it
  };
  bool start(Worker& worker);
  // The worker that calls for worker `index` go to.
  std::size_t slotOf(int index) const
  {
    return static_cast<std::size_t>(std::max(index, 0)) % this->Workers.size();
  }
  // One request and its reply on worker `index`: `request` sends the request, `readResult` reads
  // what follows a success flag; a failure flag is followed by a message, returned. A worker that
  // breaks the exchange, dies, or sends nothing for `seconds` is replaced; the message names the
  // `program` it ran and the `piece` of work it had.
  // `abortable`: the waits for the turn and for the reply ask KeepGoing (see setAbortCheck),
  // and `seconds` limits the worker's processor time on the call, not the clock's.
  std::string exchange(int index, time_t seconds, const std::string& program,
    const std::string& piece, bool abortable, const std::function<bool(int)>& request,
    const std::function<bool(int)>& readResult);
  int stop(Worker& worker, bool kill); // the wait status when it killed, else -1

  std::vector<Worker> Workers;
  WorkerSpawner Spawner; // destroyed before Workers: it kills and reaps what is left of them
  std::vector<int> KillPartitions; // sorted; see KillPartitionsVariable
  int StallWorker = -1;            // see StallWorkerVariable
  int SpinWorker = -1;             // see SpinWorkerVariable
  int TimeLimitSeconds = 0;        // see TimeLimitVariable; 0: tetgenTimeLimitSeconds()
  std::function<bool()> KeepGoing;
};

} // namespace cgmesh

#endif
