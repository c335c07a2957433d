// The cgmesh sub-commands. Each takes the arguments after its name and returns the exit status.
#ifndef cgmesh_Commands_h
#define cgmesh_Commands_h

#include "CommandLine.h"
#include "Core/Status.h"

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
// Prints the status's message as reportError() does; returns the usage-error status for an
// InvalidOption failure (arguments that cannot work, such as OUT naming IN), else the failure one.
int reportFailure(const Status& status);

// The common start of every command: with --help print the usage (exit 0); a parse error is a
// usage error (exit 2). Returns the exit status to stop with, or -1 to go on with `arguments`.
template <typename Arguments>
int startCommand(const std::vector<std::string>& commandArguments, void (*printUsage)(),
  Status (*parse)(const std::vector<std::string>&, Arguments&), Arguments& arguments)
{
  if (wantsHelp(commandArguments))
  {
    printUsage();
    return 0;
  }
  const Status status = parse(commandArguments, arguments);
  if (!status.ok())
  {
    reportError(status.message());
    return UsageErrorExitStatus;
  }
  return -1;
}

} // namespace cgmesh

#endif
