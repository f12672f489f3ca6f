# Runs scripts/benchmark.sh on two tiny frames (one S-ez, one M-d; one colour ray per pixel):
# dataset generation, discovery on every frame with ours and both PCL peers, and the
# evaluation report with the side-by-side table, end to end; then the same script on a linked
# dataset and on an empty one.
# Variables: SCRIPT (scripts/benchmark.sh), BUILD_DIR (holding apps/), WORK_DIR (emptied first).
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} -E env MID_BUILD_DIR=${BUILD_DIR}
                        MID_BENCHMARK_OUT=${WORK_DIR} MID_BENCHMARK_FRAMES=1
                        MID_BENCHMARK_SCENARIOS=S-ez,M-d MID_BENCHMARK_SUPERSAMPLING=1
                        MID_JOBS=1 "MID_BENCHMARK_METHODS=triplets gcg hough" bash ${SCRIPT}
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "benchmark.sh failed (${result}):\n${output}\n${error}")
endif()
foreach(row "\\| S-ez +\\| +1 \\|" "\\| M-d +\\| +1 \\|" "\\| total +\\| +2 \\|"
           "\\| total +\\| triplets +\\|" "\\| total +\\| gcg +\\|" "\\| total +\\| hough +\\|")
  if(NOT output MATCHES "${row}")
    message(FATAL_ERROR "the report lacks a row matching '${row}':\n${output}")
  endif()
endforeach()
foreach(name report.md results/triplets/000000/000000.json results/gcg/000001/000000.json
             results/hough/000001/000000.json)
  if(NOT EXISTS ${WORK_DIR}/${name})
    message(FATAL_ERROR "${name} was not written:\n${output}")
  endif()
endforeach()
if(output MATCHES "no result file")
  message(FATAL_ERROR "a frame had no result:\n${output}")
endif()

# A kept dataset reached through a symbolic link is read (find -L); an empty one is refused
# with a message instead of running discovery on no file.
foreach(case link empty)
  file(REMOVE_RECURSE ${WORK_DIR}_${case})
  file(MAKE_DIRECTORY ${WORK_DIR}_${case})
endforeach()
file(CREATE_LINK ${WORK_DIR}/dataset ${WORK_DIR}_link/dataset SYMBOLIC)
file(MAKE_DIRECTORY ${WORK_DIR}_empty/dataset)
foreach(case link empty)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env MID_BUILD_DIR=${BUILD_DIR}
                          MID_BENCHMARK_OUT=${WORK_DIR}_${case} MID_BENCHMARK_KEEP_DATASET=1
                          MID_JOBS=1 bash ${SCRIPT}
                  RESULT_VARIABLE result_${case} OUTPUT_VARIABLE output_${case}
                  ERROR_VARIABLE error_${case})
endforeach()
if(NOT result_link EQUAL 0 OR NOT output_link MATCHES "\\| total +\\| +2 \\|")
  message(FATAL_ERROR "benchmark.sh on a linked dataset (${result_link}):\n"
                      "${output_link}\n${error_link}")
endif()
if(result_empty EQUAL 0 OR NOT error_empty MATCHES "no frames")
  message(FATAL_ERROR "benchmark.sh accepted an empty dataset (${result_empty}):\n"
                      "${output_empty}\n${error_empty}")
endif()
