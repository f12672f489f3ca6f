#include "app_runner.h"

#include <sys/wait.h>

#include <array>
#include <cstdio>

namespace mid {
namespace test {

namespace {

/** A run longer than this counts as a hang; coreutils' timeout then ends it (exit 124). */
constexpr const char* kTimeout = "timeout --kill-after=10 600 ";
constexpr int kTimedOut = 124;

} // namespace

RunResult
runCommand (const std::string& command)
{
  RunResult result;
  FILE* pipe = popen ((kTimeout + command + " 2>&1").c_str(), "r");
  if (pipe == nullptr)
    return result;
  std::array<char, 4096> buffer{};
  std::size_t count = 0;
  while ((count = std::fread (buffer.data(), 1, buffer.size(), pipe)) > 0)
    result.output.append (buffer.data(), count);
  const int status = pclose (pipe);
  // The shell reports a child killed by signal N as exit status 128 + N.
  if (WIFEXITED (status)) {
    result.exit_code = WEXITSTATUS (status);
    result.timed_out = result.exit_code == kTimedOut;
    result.crashed = result.exit_code > 128 || result.timed_out;
  }
  else
    result.crashed = true;
  return result;
}

} // namespace test
} // namespace mid
