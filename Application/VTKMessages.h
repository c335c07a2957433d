// Collects VTK error and warning messages of an algorithm instead of letting VTK print its
// multi-line reports, so that the command line can print one clear line per problem.
#ifndef cgmesh_VTKMessages_h
#define cgmesh_VTKMessages_h

#include "vtkCommand.h"

#include <string>
#include <vector>

class vtkObject;

namespace cgmesh
{

class VTKMessageCollector : public vtkCommand
{
public:
  static VTKMessageCollector* New() { return new VTKMessageCollector; }

  // Observes ErrorEvent and WarningEvent of `object` and, for an algorithm, of its executive.
  void watch(vtkObject* object);

  void Execute(vtkObject* caller, unsigned long eventId, void* callData) override;

  const std::vector<std::string>& errors() const { return this->Errors; }
  const std::vector<std::string>& warnings() const { return this->Warnings; }
  // The first error, or `fallback` when there was none.
  std::string firstError(const std::string& fallback) const;

private:
  std::vector<std::string> Errors;
  std::vector<std::string> Warnings;
};

} // namespace cgmesh

#endif
