# Fails unless the umbrella header c2f/c2f.hpp includes every public header of the library
# (all headers under an include/c2f/ folder of modules/ and adapters/, except detail/ internals and the
# optional GPL-3 backend). Invoked by CTest with -DSOURCE_DIR=<c2f source tree>.
file(READ "${SOURCE_DIR}/modules/umbrella/include/c2f/c2f.hpp" umbrella)
file(GLOB_RECURSE headers RELATIVE "${SOURCE_DIR}"
  "${SOURCE_DIR}/modules/*.hpp" "${SOURCE_DIR}/adapters/*.hpp")
list(FILTER headers INCLUDE REGEX "/include/c2f/")
set(missing)
foreach(header IN LISTS headers)
  string(REGEX REPLACE "^.*/include/" "" include "${header}")
  if(include MATCHES "/detail/" OR include STREQUAL "c2f/c2f.hpp" OR include MATCHES "kolmogorov")
    continue()
  endif()
  string(FIND "${umbrella}" "#include \"${include}\"" position)
  if(position EQUAL -1)
    list(APPEND missing "${include}")
  endif()
endforeach()
if(missing)
  list(JOIN missing "\n  " text)
  message(FATAL_ERROR "c2f/c2f.hpp does not include:\n  ${text}")
endif()
list(LENGTH headers count)
message("c2f/c2f.hpp includes every public header (${count} headers checked)")
