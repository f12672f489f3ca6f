#pragma once

#include <string>

namespace mid {
namespace test {

/** \brief How a program run ended. */
struct RunResult
{
  /** \brief Exit status, or -1 if the program was killed by a signal (a crash). */
  int exit_code = -1;
  bool crashed = false;
  /** \brief Everything the program wrote to stdout and stderr. */
  std::string output;
};

/** \brief Run `command` through the shell, capturing stdout and stderr together. */
RunResult
runCommand (const std::string& command);

} // namespace test
} // namespace mid
