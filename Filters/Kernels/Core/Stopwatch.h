// Wall-clock seconds since a start: the one timer of the project.
#ifndef cgmesh_Stopwatch_h
#define cgmesh_Stopwatch_h

#include <chrono>

namespace cgmesh
{

class Stopwatch
{
public:
  Stopwatch()
    : Start(Clock::now())
  {
  }

  double seconds() const
  {
    return std::chrono::duration<double>(Clock::now() - this->Start).count();
  }

  // Seconds since the start, and starts again.
  double lap()
  {
    const auto now = Clock::now();
    const double elapsed = std::chrono::duration<double>(now - this->Start).count();
    this->Start = now;
    return elapsed;
  }

private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point Start;
};

} // namespace cgmesh

#endif
