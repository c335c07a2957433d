#include "VTKMessages.h"

#include "vtkAlgorithm.h"
#include "vtkExecutive.h"
#include "vtkObject.h"

namespace cgmesh
{

namespace
{

// VTK messages read "vtkClassName (0x1234): text\n"; keep the text only.
std::string stripObjectDescription(const char* message)
{
  std::string text = message ? message : "";
  const size_t prefixEnd = text.find("): ");
  if (prefixEnd != std::string::npos)
  {
    text = text.substr(prefixEnd + 3);
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
  {
    text.pop_back();
  }
  return text;
}

} // namespace

void VTKMessageCollector::watch(vtkObject* object)
{
  object->AddObserver(vtkCommand::ErrorEvent, this);
  object->AddObserver(vtkCommand::WarningEvent, this);
  // The executive adds its own multi-line "returned failure" report after the algorithm's error.
  if (vtkAlgorithm* algorithm = vtkAlgorithm::SafeDownCast(object))
  {
    algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this);
    algorithm->GetExecutive()->AddObserver(vtkCommand::WarningEvent, this);
  }
}

void VTKMessageCollector::Execute(vtkObject*, unsigned long eventId, void* callData)
{
  const std::string text = stripObjectDescription(static_cast<const char*>(callData));
  if (eventId == vtkCommand::ErrorEvent)
  {
    this->Errors.push_back(text);
  }
  else
  {
    this->Warnings.push_back(text);
  }
}

std::string VTKMessageCollector::firstError(const std::string& fallback) const
{
  return this->Errors.empty() ? fallback : this->Errors.front();
}

} // namespace cgmesh
