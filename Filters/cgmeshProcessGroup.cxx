#include "cgmeshProcessGroup.h"

#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"

namespace cgmesh
{

std::unique_ptr<ProcessGroup> ProcessGroup::ofGlobalController()
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (!controller || controller->GetNumberOfProcesses() < 2)
  {
    return nullptr;
  }
  return std::make_unique<ProcessGroup>(controller);
}

ProcessGroup::ProcessGroup(vtkMultiProcessController* controller)
  : Controller(controller)
  , Rank(controller->GetLocalProcessId())
  , Size(controller->GetNumberOfProcesses())
{
}

int ProcessGroup::firstFailure(bool ok) const
{
  const int mine = ok ? this->Size : this->Rank;
  int lowest = mine;
  this->Controller->AllReduce(&mine, &lowest, 1, vtkCommunicator::MIN_OP);
  return lowest < this->Size ? lowest : -1;
}

double ProcessGroup::sum(double value) const
{
  double total = 0;
  this->Controller->AllReduce(&value, &total, 1, vtkCommunicator::SUM_OP);
  return total;
}

long long ProcessGroup::sum(long long value) const
{
  long long total = 0;
  this->Controller->AllReduce(&value, &total, 1, vtkCommunicator::SUM_OP);
  return total;
}

long long ProcessGroup::maximum(long long value) const
{
  long long largest = 0;
  this->Controller->AllReduce(&value, &largest, 1, vtkCommunicator::MAX_OP);
  return largest;
}

std::vector<long long> ProcessGroup::gather(long long value) const
{
  std::vector<long long> values(this->Size);
  this->Controller->AllGather(&value, values.data(), 1);
  return values;
}

template <typename T>
std::vector<T> ProcessGroup::gatherValues(
  const std::vector<T>& values, std::vector<long long>& offsets) const
{
  const std::vector<long long> lengths = this->gather(static_cast<long long>(values.size()));
  offsets.assign(this->Size + 1, 0);
  for (int r = 0; r < this->Size; ++r)
  {
    offsets[r + 1] = offsets[r] + lengths[r];
  }
  std::vector<T> all(static_cast<std::size_t>(offsets.back()));
  std::vector<vtkIdType> receiveLengths(lengths.begin(), lengths.end());
  std::vector<vtkIdType> receiveOffsets(offsets.begin(), offsets.end() - 1);
  // A pointer even for empty vectors: VTK forwards it to MPI as is.
  T none{};
  this->Controller->AllGatherV(values.empty() ? &none : values.data(),
    all.empty() ? &none : all.data(), static_cast<vtkIdType>(values.size()), receiveLengths.data(),
    receiveOffsets.data());
  return all;
}

std::vector<double> ProcessGroup::gather(
  const std::vector<double>& values, std::vector<long long>& offsets) const
{
  return this->gatherValues(values, offsets);
}

std::vector<long long> ProcessGroup::gather(
  const std::vector<long long>& values, std::vector<long long>& offsets) const
{
  return this->gatherValues(values, offsets);
}

std::vector<char> ProcessGroup::gather(
  const std::vector<char>& values, std::vector<long long>& offsets) const
{
  return this->gatherValues(values, offsets);
}

} // namespace cgmesh
