# Helpers that give every target of ours the same warnings, sanitizer flags and layout.

# mid_set_warnings(<target>): our warnings and sanitizer flags, on our own targets only.
# Dependency headers come in as SYSTEM includes (PCL, OpenCV, VTK, Eigen are imported targets),
# so their warnings do not count, and dependency libraries are never rebuilt with sanitizers.
function(mid_set_warnings target)
  get_target_property(type ${target} TYPE)
  if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                             -Wnon-virtual-dtor -Wold-style-cast)
    # -Wconversion: narrowing between integer and floating-point types. Clang's -Wconversion also
    # holds -Wsign-conversion (GCC's does not, for C++); in our code that only flags int loop
    # counters used as std::array indices, so both compilers check the same narrowing. Clang's
    # -Wpedantic also flags the anonymous structs that PCL's PCL_ADD_POINT4D expands to in a
    # custom point type (GCC does not: the macro comes from a system header). .clang-tidy
    # passes the same three flags.
    if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
      target_compile_options(${target} PRIVATE -Wno-sign-conversion -Wno-gnu-anonymous-struct
                                               -Wno-nested-anon-types)
    endif()
    if(MID_WARNINGS_AS_ERRORS)
      target_compile_options(${target} PRIVATE -Werror)
    endif()
  endif()
  set(sanitizers "")
  if(MID_SANITIZE)
    set(sanitizers address,undefined)
    # GCC's documentation warns that sanitizer instrumentation makes -Wmaybe-uninitialized
    # report false positives (seen in <regex> from libstdc++); the normal build keeps it.
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
      target_compile_options(${target} PRIVATE -Wno-maybe-uninitialized)
    endif()
  endif()
  if(MID_BUILD_FUZZERS)
    # Coverage instrumentation for libFuzzer; the fuzz targets themselves add -fsanitize=fuzzer.
    set(sanitizers fuzzer-no-link,address,undefined)
  endif()
  if(sanitizers)
    target_compile_options(${target} PRIVATE -fsanitize=${sanitizers} -fno-omit-frame-pointer
                                             -fno-sanitize-recover=all)
    # Eigen stops trusting malloc's 16-byte alignment when __SANITIZE_ADDRESS__ is defined (GCC)
    # and then offsets its blocks, so a cloud allocated in our sanitized code and freed in
    # uninstrumented code (PCL, a consumer) is a bad free. ASan's malloc is 16-byte aligned, and
    # PCL in the same process already relies on it: keep one allocation scheme everywhere.
    target_compile_definitions(${target} PRIVATE EIGEN_MALLOC_ALREADY_ALIGNED=1)
    # A static library only needs the runtime where it is linked: its users (our tests, apps,
    # and a consumer of an installed sanitized build) get the link flag through the interface.
    if(type STREQUAL "STATIC_LIBRARY")
      target_link_options(${target} INTERFACE -fsanitize=address,undefined)
    else()
      target_link_options(${target} PRIVATE -fsanitize=address,undefined)
    endif()
  endif()
endfunction()

# mid_add_module(<name> SOURCES ... DEPENDS ...): library mid_<name> with alias mid::<name>,
# headers under <name>/include/mid/<name>/, installed and exported.
function(mid_add_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
  set(target mid_${name})
  add_library(${target} ${ARG_SOURCES})
  add_library(mid::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name}
                                             POSITION_INDEPENDENT_CODE ON
                                             VERSION ${PROJECT_VERSION}
                                             SOVERSION ${PROJECT_VERSION_MAJOR})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(${target} PUBLIC ${ARG_DEPENDS})
  target_compile_features(${target} PUBLIC cxx_std_17)
  mid_set_warnings(${target})
  install(TARGETS ${target} EXPORT midTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(DIRECTORY include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endfunction()

# mid_add_app(<name> SOURCES ... DEPENDS ...): an installed command-line program.
function(mid_add_app name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPENDS})
  mid_set_warnings(${name})
  install(TARGETS ${name} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endfunction()
