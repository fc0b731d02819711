# Installation: every module target into one export set c2fTargets (namespace c2f::),
# headers, and a relocatable c2fConfig.cmake that finds the dependencies. A build-tree
# export() lets consumers use the build directory directly as well.
include(CMakePackageConfigHelpers)

get_property(c2f_targets GLOBAL PROPERTY C2F_MODULE_TARGETS)
get_property(c2f_include_dirs GLOBAL PROPERTY C2F_MODULE_INCLUDE_DIRS)

install(TARGETS ${c2f_targets}
  EXPORT c2fTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})

foreach(dir IN LISTS c2f_include_dirs)
  install(DIRECTORY ${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()

set(c2f_config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/c2f)
install(EXPORT c2fTargets NAMESPACE c2f:: DESTINATION ${c2f_config_dir})
export(EXPORT c2fTargets NAMESPACE c2f:: FILE ${PROJECT_BINARY_DIR}/c2fTargets.cmake)

configure_package_config_file(cmake/c2fConfig.cmake.in
  ${PROJECT_BINARY_DIR}/c2fConfig.cmake
  INSTALL_DESTINATION ${c2f_config_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/c2fConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/c2fConfig.cmake ${PROJECT_BINARY_DIR}/c2fConfigVersion.cmake
  DESTINATION ${c2f_config_dir})
