# Runs Doxygen and fails on any warning: the target `doc` and the test Doxygen.NoWarnings.
#   cmake -DDOXYGEN=<doxygen> -DDOXYFILE=<build>/doc/Doxyfile -DWARNINGS_LOG=<file> \
#         -P run_doxygen.cmake
# The Doxyfile sets WARN_AS_ERROR = FAIL_ON_WARNINGS (non-zero exit after the whole run) and
# WARN_LOGFILE (where the warnings go instead of the terminal): both are checked, and the
# warnings are printed, as file:line: message.
foreach(variable DOXYGEN DOXYFILE WARNINGS_LOG)
  if(NOT ${variable})
    message(FATAL_ERROR "run_doxygen.cmake: -D${variable}=... is missing")
  endif()
endforeach()

file(REMOVE "${WARNINGS_LOG}")
get_filename_component(working_dir "${DOXYFILE}" DIRECTORY)
execute_process(COMMAND "${DOXYGEN}" "${DOXYFILE}"
                WORKING_DIRECTORY "${working_dir}"
                RESULT_VARIABLE result)

set(warnings "")
if(EXISTS "${WARNINGS_LOG}")
  file(READ "${WARNINGS_LOG}" warnings)
endif()
string(STRIP "${warnings}" warnings)
if(NOT result EQUAL 0 OR NOT warnings STREQUAL "")
  string(REGEX MATCHALL ": (warning|error): " found "${warnings}")
  list(LENGTH found count)
  message("${warnings}") # as it is: FATAL_ERROR would re-wrap the lines
  message(FATAL_ERROR "Doxygen: ${count} warning(s) (exit code ${result}), listed above; "
                      "any warning fails the API documentation")
endif()
message(STATUS "Doxygen: no warnings")
