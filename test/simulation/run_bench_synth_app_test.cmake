# Runs pcl_multi_instance_bench_synth: a small dataset is written completely (BOP layout,
# scenarios.json, models_info.json, preview) and identically for one seed, and bad arguments
# fail with one line and leave nothing behind.
# Variables: APP (the executable), TEXTURE_DIR, WORK_DIR (scratch folder, emptied first).
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

function(run_app out_dir)
  # One colour ray per pixel keeps the test quick in debug and sanitizer builds.
  execute_process(COMMAND ${APP} -texture_dir ${TEXTURE_DIR} -out_dir ${WORK_DIR}/${out_dir}
                          -supersampling 1 ${ARGN}
                  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${APP} ${ARGN} failed (${result}):\n${output}\n${error}")
  endif()
  file(GLOB_RECURSE leftovers ${WORK_DIR}/${out_dir}/*.partial.*)
  if(leftovers)
    message(FATAL_ERROR "temporary files left: ${leftovers}")
  endif()
endfunction()

set(args -seed 4 -frames 2 -scenarios rows,S-d)
run_app(first ${args} -preview ${WORK_DIR}/first/preview.png -preview_scale 0.25)
run_app(second ${args})

# -instances_per_type 2: every repeated product of an S-d frame appears exactly twice.
run_app(pairs -seed 4 -frames 1 -scenarios S-d -instances_per_type 2)
file(READ ${WORK_DIR}/pairs/000000/scene_gt.json pair_gt)
string(REGEX MATCHALL "\"obj_id\": [0-9]+" pair_ids "${pair_gt}")
list(SORT pair_ids)
set(repeated_twice FALSE)
list(REMOVE_DUPLICATES pair_ids)
foreach(id ${pair_ids})
  string(REGEX MATCHALL "${id}[,}]" copies "${pair_gt}")
  list(LENGTH copies count)
  if(count GREATER 2)
    message(FATAL_ERROR "${id} appears ${count} times in a pair frame:\n${pair_gt}")
  elseif(count EQUAL 2)
    set(repeated_twice TRUE)
  endif()
endforeach()
if(NOT repeated_twice)
  message(FATAL_ERROR "no product appears twice in a pair frame:\n${pair_gt}")
endif()

# The BOP layout: scene 000000 holds the rows frames, 000001 the S-d ones.
foreach(name scenarios.json models_info.json camera.json preview.png
             000000/scene_camera.json 000000/scene_gt.json 000000/scene_gt_info.json
             000001/scene_gt.json 000000/rgb/000000.png 000000/depth/000001.png
             000001/pcd/000001.pcd 000001/mask_visib/000001_000000.png)
  if(NOT EXISTS ${WORK_DIR}/first/${name})
    message(FATAL_ERROR "${name} was not written")
  endif()
endforeach()
file(READ ${WORK_DIR}/first/scenarios.json scenarios)
if(NOT scenarios MATCHES "\"000000\": \"rows\"" OR NOT scenarios MATCHES "\"000001\": \"S-d\"")
  message(FATAL_ERROR "scenarios.json does not name the scenes:\n${scenarios}")
endif()
file(READ ${WORK_DIR}/first/000001/scene_gt.json gt)
foreach(expected "\"0\": [{\"cam_R_m2c\": [" "\"1\": [" "\"cam_t_m2c\": [" "\"obj_id\": ")
  string(FIND "${gt}" "${expected}" found)
  if(found EQUAL -1)
    message(FATAL_ERROR "scene_gt.json lacks ${expected}")
  endif()
endforeach()
file(READ ${WORK_DIR}/first/000001/pcd/000001.pcd header LIMIT 400)
if(NOT header MATCHES "WIDTH 640" OR NOT header MATCHES "HEIGHT 480")
  message(FATAL_ERROR "the PCD is not an organized VGA cloud:\n${header}")
endif()

# Same seed, same files (the preview aside).
file(GLOB_RECURSE written RELATIVE ${WORK_DIR}/second ${WORK_DIR}/second/*)
list(LENGTH written count)
if(count LESS 20)
  message(FATAL_ERROR "only ${count} files written: ${written}")
endif()
foreach(name ${written})
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK_DIR}/first/${name}
                          ${WORK_DIR}/second/${name} RESULT_VARIABLE different)
  if(different)
    message(FATAL_ERROR "${name} differs between two runs with the same seed")
  endif()
endforeach()

function(expect_failure label out_dir)
  execute_process(COMMAND ${APP} -texture_dir ${TEXTURE_DIR} -out_dir ${out_dir} ${ARGN}
                  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
  if(result EQUAL 0)
    message(FATAL_ERROR "${label}: ${APP} ${ARGN} succeeded")
  endif()
  string(STRIP "${error}" error)
  string(REGEX MATCHALL "\n" newlines "${error}")
  list(LENGTH newlines extra_lines)
  if(error STREQUAL "" OR NOT extra_lines EQUAL 0)
    message(FATAL_ERROR "${label}: expected a one-line error, got:\n${error}")
  endif()
endfunction()

set(bad ${WORK_DIR}/bad)
expect_failure("output folder not empty" ${WORK_DIR}/first -frames 1)
expect_failure("unknown scenario" ${bad} -scenarios S-ez,easy)
expect_failure("scenario twice" ${bad} -scenarios rows,rows)
expect_failure("no frames" ${bad} -frames 0)
expect_failure("bad seed" ${bad} -seed 1x)
expect_failure("bad preview scale" ${bad} -preview ${bad}.png -preview_scale 2)
expect_failure("one copy per type" ${bad} -instances_per_type 1)
expect_failure("ten copies per type" ${bad} -instances_per_type 10)
expect_failure("unknown option" ${bad} -bogus 1)
expect_failure("missing value" ${bad} -frames)
expect_failure("supersampling above the renderer's limit" ${bad} -supersampling 17)
expect_failure("unwritable preview" ${bad} -frames 1 -scenarios none -supersampling 1
               -preview ${WORK_DIR}/missing/preview.png)
if(EXISTS ${bad})
  message(FATAL_ERROR "a failed run left ${bad} behind")
endif()
