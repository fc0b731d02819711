# Builds and runs a consumer project of c2f. Invoked by CTest with -D variables:
#   MODE            install: install the c2f build tree into a scratch prefix and give it to the
#                   consumer's find_package; subdirectory: the consumer adds c2f's sources
#   C2F_BUILD_DIR, C2F_SOURCE_DIR, CONSUMER_SOURCE, WORK_DIR, GENERATOR, BUILD_TYPE,
#   CXX_COMPILER, CXX_FLAGS, LINKER_FLAGS
#   CONSUMER_ARGS   extra configure arguments for the consumer (a ;-list)
file(REMOVE_RECURSE "${WORK_DIR}")

function(run_step name)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}")
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "package test: ${name} failed (${result}):\n${out}\n${err}")
  endif()
endfunction()

set(consumer_args "-DC2F_SOURCE_DIR=${C2F_SOURCE_DIR}")
if(MODE STREQUAL "install")
  run_step(install ${CMAKE_COMMAND} --install "${C2F_BUILD_DIR}" --prefix "${WORK_DIR}/prefix")
  if(EXISTS "${WORK_DIR}/prefix/bin/c2f-stereo")
    message(FATAL_ERROR "package test: installing the library installed the c2f-stereo tool")
  endif()
  list(APPEND consumer_args "-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix")
endif()
run_step(configure ${CMAKE_COMMAND} -S "${CONSUMER_SOURCE}" -B "${WORK_DIR}/build" -G "${GENERATOR}"
  ${consumer_args} ${CONSUMER_ARGS} "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}"
  "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}" "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}"
  "-DCMAKE_EXE_LINKER_FLAGS=${LINKER_FLAGS}")
get_filename_component(consumer "${CONSUMER_SOURCE}" NAME)
run_step(build ${CMAKE_COMMAND} --build "${WORK_DIR}/build")
run_step(run "${WORK_DIR}/build/${consumer}")
