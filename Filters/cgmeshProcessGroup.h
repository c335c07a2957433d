// The processes that hold the pieces of one mesh (ParaView's MPI ranks under pvbatch or pvserver),
// seen through VTK's vtkMultiProcessController: the few collective calls the distributed steps
// make. Every process must make the same calls in the same order.
#ifndef cgmeshProcessGroup_h
#define cgmeshProcessGroup_h

#include <cstdint>
#include <memory>
#include <vector>

class vtkMultiProcessController;

namespace cgmesh
{

class ProcessGroup
{
public:
  // The group of ParaView's (VTK's global) controller when it runs more than one process, else
  // nothing: one process needs none of the distributed steps.
  static std::unique_ptr<ProcessGroup> ofGlobalController();

  explicit ProcessGroup(vtkMultiProcessController* controller);

  int rank() const { return this->Rank; }
  int size() const { return this->Size; }
  vtkMultiProcessController* controller() const { return this->Controller; }

  // The lowest rank whose `ok` is false, or -1 when every process passed. Called by all processes
  // after each step that can fail, so that one process's error ends every process at the same
  // point instead of leaving the others waiting in a later exchange.
  int firstFailure(bool ok) const;

  double sum(double value) const;
  long long sum(long long value) const;
  long long maximum(long long value) const;
  // Each process's value, in rank order.
  std::vector<long long> gather(long long value) const;
  // The values of every process, concatenated in rank order; process r's lie in
  // [offsets[r], offsets[r + 1]).
  std::vector<double> gather(
    const std::vector<double>& values, std::vector<long long>& offsets) const;
  std::vector<long long> gather(
    const std::vector<long long>& values, std::vector<long long>& offsets) const;
  std::vector<char> gather(const std::vector<char>& values, std::vector<long long>& offsets) const;

private:
  template <typename T>
  std::vector<T> gatherValues(const std::vector<T>& values, std::vector<long long>& offsets) const;

  vtkMultiProcessController* Controller;
  int Rank;
  int Size;
};

} // namespace cgmesh

#endif
