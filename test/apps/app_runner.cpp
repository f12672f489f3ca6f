#include "app_runner.h"

#include <sys/wait.h>

#include <array>
#include <cstdio>

namespace mid {
namespace test {

RunResult
runCommand (const std::string& command)
{
  RunResult result;
  FILE* pipe = popen ((command + " 2>&1").c_str (), "r");
  if (pipe == nullptr)
    return result;
  std::array<char, 4096> buffer{};
  std::size_t count = 0;
  while ((count = std::fread (buffer.data (), 1, buffer.size (), pipe)) > 0)
    result.output.append (buffer.data (), count);
  const int status = pclose (pipe);
  // The shell reports a child killed by signal N as exit status 128 + N.
  if (WIFEXITED (status)) {
    result.exit_code = WEXITSTATUS (status);
    result.crashed = result.exit_code > 128;
  }
  else
    result.crashed = true;
  return result;
}

} // namespace test
} // namespace mid
