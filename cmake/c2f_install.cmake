# Installation (when C2F_INSTALL is on: by default only for the top-level project, as fmt's
# FMT_INSTALL). The library is one package, c2f, in components that each bring only their own
# third-party dependencies:
#   core        c2f::core, c2f::lift, c2f::driver, c2f::cooperative,
#               c2f::lbp, c2f::icm                                          (none)
#   graphcut    c2f::maxflow, c2f::graphcut, c2f::run (the run layer)      (Boost headers)
#   kolmogorov  c2f::kolmogorov_maxflow, when built                        (libmaxflow, GPL-3)
#   vision      c2f::vision, c2f::stereo, c2f::segmentation                (OpenCV, Eigen)
#   coop        c2f::coop, the cooperative-cut solvers, c2f::coop_run      (Ceres)
#   all         c2f::c2f, everything but kolmogorov
#   import      c2f::import, `import c2f;`, when the toolchain builds modules (CMake >= 3.28)
# Each component has its own export file; c2fConfig.cmake loads the requested ones (all when
# none are named) after finding their dependencies. A build-tree export() lets consumers use
# the build directory directly as well. The command-line tools install separately
# (cmake --install BUILD --component tools), never with the library.
include(CMakePackageConfigHelpers)

set(c2f_config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/c2f)
set(c2f_components core graphcut kolmogorov vision coop all import)
set(c2f_built_components)
foreach(component IN LISTS c2f_components)
  get_property(targets GLOBAL PROPERTY C2F_COMPONENT_TARGETS_${component})
  if(NOT targets)
    continue()
  endif()
  list(APPEND c2f_built_components ${component})
  # The module's interface unit installs with it; consumers build its BMI themselves.
  set(module_files)
  set(module_exports)
  if(component STREQUAL "import")
    set(module_files FILE_SET CXX_MODULES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/c2f/import)
    set(module_exports CXX_MODULES_DIRECTORY cxx-modules)
  endif()
  install(TARGETS ${targets}
    EXPORT c2f-${component}-targets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
    INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
    ${module_files})
  install(EXPORT c2f-${component}-targets NAMESPACE c2f:: DESTINATION ${c2f_config_dir}
    ${module_exports})
  export(EXPORT c2f-${component}-targets NAMESPACE c2f::
    FILE ${PROJECT_BINARY_DIR}/c2f-${component}-targets.cmake ${module_exports})
endforeach()

get_property(c2f_include_dirs GLOBAL PROPERTY C2F_MODULE_INCLUDE_DIRS)
foreach(dir IN LISTS c2f_include_dirs)
  install(DIRECTORY ${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()

configure_package_config_file(cmake/c2fConfig.cmake.in
  ${PROJECT_BINARY_DIR}/c2fConfig.cmake
  INSTALL_DESTINATION ${c2f_config_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/c2fConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/c2fConfig.cmake ${PROJECT_BINARY_DIR}/c2fConfigVersion.cmake
  DESTINATION ${c2f_config_dir})
