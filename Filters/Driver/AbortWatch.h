// Aborting a run while its threads wait on worker processes. The front end's progress and abort
// hooks may only be called on the thread that started the run (a GUI takes the abort button's
// click while it reports progress), but a TetGen call on any thread can take minutes. The watch
// is polled from everywhere: on the calling thread it re-reports progress and asks the front end;
// on the others it tells what the calling thread last found. Once an abort is seen it stays.
#ifndef cgmesh_AbortWatch_h
#define cgmesh_AbortWatch_h

#include "PhaseReporter.h"

#include <atomic>
#include <functional>
#include <thread>

namespace cgmesh
{

class AbortWatch
{
public:
  // `abortRequested` may be empty (never aborts); made on the calling thread.
  AbortWatch(std::function<bool()> abortRequested, PhaseReporter& reporter);

  // Whether the run goes on. Any thread; see above.
  bool keepGoing();
  // Whether an abort was seen. Any thread.
  bool aborted() const { return this->Aborted.load(std::memory_order_acquire); }

private:
  std::function<bool()> AbortRequested;
  PhaseReporter& Reporter;
  const std::thread::id Caller;
  std::atomic<bool> Aborted{ false };
};

} // namespace cgmesh

#endif
