// Every kernel returns a Status instead of throwing: failures must never escape a parallel region.
#ifndef cgmesh_Status_h
#define cgmesh_Status_h

#include <string>
#include <utility>

namespace cgmesh
{

class Status
{
public:
  static Status success() { return Status(true, std::string()); }
  static Status failure(std::string message) { return Status(false, std::move(message)); }

  bool ok() const { return this->Ok; }
  const std::string& message() const { return this->Message; }

private:
  Status(bool ok, std::string message)
    : Ok(ok)
    , Message(std::move(message))
  {
  }

  bool Ok;
  std::string Message;
};

} // namespace cgmesh

#endif
