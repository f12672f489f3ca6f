# Installs the CMake package so that downstream projects can
#   find_package(mid CONFIG REQUIRED)
#   target_link_libraries(app PRIVATE mid::features)
include(CMakePackageConfigHelpers)
set(MID_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/mid)

install(EXPORT midTargets NAMESPACE mid:: DESTINATION ${MID_INSTALL_CMAKEDIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/midConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/midConfig.cmake
  INSTALL_DESTINATION ${MID_INSTALL_CMAKEDIR})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/midConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/midConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/midConfigVersion.cmake
        DESTINATION ${MID_INSTALL_CMAKEDIR})
