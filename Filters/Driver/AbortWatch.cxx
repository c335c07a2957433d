#include "AbortWatch.h"

#include <utility>

namespace cgmesh
{

AbortWatch::AbortWatch(std::function<bool()> abortRequested, PhaseReporter& reporter)
  : AbortRequested(std::move(abortRequested))
  , Reporter(reporter)
  , Caller(std::this_thread::get_id())
{
}

bool AbortWatch::keepGoing()
{
  if (std::this_thread::get_id() == this->Caller && !this->aborted())
  {
    this->Reporter.heartbeat();
    if (this->AbortRequested && this->AbortRequested())
    {
      this->Aborted.store(true, std::memory_order_release);
    }
  }
  return !this->aborted();
}

} // namespace cgmesh
