// Every kernel returns a Status instead of throwing: failures must never escape a parallel region.
// A failure has a kind, for callers that react to what went wrong rather than to its wording.
#ifndef cgmesh_Status_h
#define cgmesh_Status_h

#include <string>
#include <utility>

namespace cgmesh
{

enum class ErrorKind
{
  None,          // success
  InvalidInput,  // the mesh cannot be refined as given (bad ids, non-finite points, flat tets)
  InvalidOption, // an option is out of range or does not fit the input
  SizeLimit,     // the size guard refused a forecast refinement
  OutOfMemory,
  TaskFailed, // a parallel task threw: the message is the task's own
  Internal    // a kernel broke its own contract (an improper colouring, a missing template)
};

class Status
{
public:
  static Status success() { return Status(ErrorKind::None, std::string()); }
  static Status failure(std::string message)
  {
    return Status(ErrorKind::Internal, std::move(message));
  }
  static Status failure(ErrorKind kind, std::string message)
  {
    return Status(kind, std::move(message));
  }

  bool ok() const { return this->Kind == ErrorKind::None; }
  ErrorKind kind() const { return this->Kind; }
  const std::string& message() const { return this->Message; }

private:
  Status(ErrorKind kind, std::string message)
    : Kind(kind)
    , Message(std::move(message))
  {
  }

  ErrorKind Kind;
  std::string Message;
};

} // namespace cgmesh

#endif
