// The cgmesh sub-commands. Each takes the arguments after its name and returns the exit status.
#ifndef cgmesh_Commands_h
#define cgmesh_Commands_h

#include <string>
#include <vector>

namespace cgmesh
{

int runRefineCommand(const std::vector<std::string>& arguments);
int runGenerateCommand(const std::vector<std::string>& arguments);
int runCheckCommand(const std::vector<std::string>& arguments);
int runTetGenCommand(const std::vector<std::string>& arguments);

// Prints "cgmesh: error: <message>" on stderr and returns the exit status for errors.
int reportError(const std::string& message);
// Exit status for command-line usage errors (distinct from run-time failures).
constexpr int UsageErrorExitStatus = 2;
constexpr int FailureExitStatus = 1;

} // namespace cgmesh

#endif
