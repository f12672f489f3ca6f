#pragma once

#include <string>

namespace mid {
namespace test {

/** \brief How a program run ended. */
struct RunResult
{
  /** \brief Exit status, or -1 if the program was killed by a signal (a crash). */
  int exit_code = -1;
  /** \brief Killed by a signal, or ended after hanging (see timed_out): never acceptable. */
  bool crashed = false;
  /** \brief Still running after 10 minutes, and ended by the runner. */
  bool timed_out = false;
  /** \brief Everything the program wrote to stdout and stderr. */
  std::string output;
};

/** \brief Run `command` through the shell, capturing stdout and stderr together; a run that
  * takes longer than 10 minutes is ended and counts as a crash.
  */
RunResult
runCommand (const std::string& command);

} // namespace test
} // namespace mid
