# Installs the c2f build tree into a scratch prefix, then configures, builds and runs the
# consumer project against it with find_package(c2f). Invoked by CTest with -D variables:
# C2F_BUILD_DIR, CONSUMER_SOURCE, WORK_DIR, GENERATOR, BUILD_TYPE, CXX_COMPILER, CXX_FLAGS,
# LINKER_FLAGS.
file(REMOVE_RECURSE "${WORK_DIR}")

function(run_step name)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}")
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "package test: ${name} failed (${result}):\n${err}")
  endif()
endfunction()

run_step(install ${CMAKE_COMMAND} --install "${C2F_BUILD_DIR}" --prefix "${WORK_DIR}/prefix")
run_step(configure ${CMAKE_COMMAND} -S "${CONSUMER_SOURCE}" -B "${WORK_DIR}/build" -G "${GENERATOR}"
  "-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix" "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}"
  "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}" "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}"
  "-DCMAKE_EXE_LINKER_FLAGS=${LINKER_FLAGS}")
run_step(build ${CMAKE_COMMAND} --build "${WORK_DIR}/build")
run_step(run "${WORK_DIR}/build/consumer")
