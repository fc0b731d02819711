# c2f_add_library(NAME <name> [COMPONENT <component>] [SOURCES ...] [DEPENDS ...]
#                [INCLUDE_DIR <dir>])
#
# Declares one library (a folder of modules/ or adapters/): target c2f_<name>, alias c2f::<name>, exported as
# c2f::<name> in the package component <component> (default core; see c2f_install.cmake),
# public headers under <dir> (default: include/ next to the CMakeLists). Modules without
# sources become INTERFACE (header-only) targets. Sources see the uninstalled support headers
# (modules/core/support: c2f/support/*.hpp, the input layer, number text, checked sizes,
# parallel_for, ...); public headers never include them.
function(c2f_add_library)
  cmake_parse_arguments(ARG "" "NAME;INCLUDE_DIR;COMPONENT" "SOURCES;DEPENDS" ${ARGN})
  if(NOT ARG_COMPONENT)
    set(ARG_COMPONENT core)
  endif()
  set(target c2f_${ARG_NAME})
  if(NOT ARG_INCLUDE_DIR)
    set(ARG_INCLUDE_DIR ${CMAKE_CURRENT_SOURCE_DIR}/include)
  endif()
  if(ARG_SOURCES)
    add_library(${target} ${ARG_SOURCES})
    set(scope PUBLIC)
    target_compile_features(${target} PUBLIC cxx_std_20)
    target_compile_options(${target} PRIVATE
      $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion>)
    set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    target_include_directories(${target} PRIVATE $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/modules/core/support>)
  else()
    add_library(${target} INTERFACE)
    set(scope INTERFACE)
    target_compile_features(${target} INTERFACE cxx_std_20)
  endif()
  add_library(c2f::${ARG_NAME} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${ARG_NAME})
  target_include_directories(${target} ${scope}
    $<BUILD_INTERFACE:${ARG_INCLUDE_DIR}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  if(ARG_DEPENDS)
    target_link_libraries(${target} ${scope} ${ARG_DEPENDS})
  endif()
  set_property(GLOBAL APPEND PROPERTY C2F_COMPONENT_TARGETS_${ARG_COMPONENT} ${target})
  set_property(GLOBAL APPEND PROPERTY C2F_MODULE_INCLUDE_DIRS ${ARG_INCLUDE_DIR})
endfunction()

# Warnings for the project's own executables (tests, examples, benchmarks).
function(c2f_warnings target)
  target_compile_options(${target} PRIVATE
    $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow>)
endfunction()
