# Checks a compile-time refusal: SOURCE compiles with -DLEX_KERNEL=${GOOD}, and fails with
# -DLEX_KERNEL=${BAD} with an error that contains MESSAGE.
# Arguments: CXX, INCLUDE (the package's include folder), SOURCE, GOOD, BAD, MESSAGE.
foreach(kernel GOOD BAD)
  execute_process(COMMAND "${CXX}" -std=c++17 -fsyntax-only "-I${INCLUDE}" "-DLEX_KERNEL=${${kernel}}" "${SOURCE}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(kernel STREQUAL GOOD AND NOT rc EQUAL 0)
    message(FATAL_ERROR "${SOURCE} does not compile with ${GOOD}:\n${err}")
  endif()
  if(kernel STREQUAL BAD)
    if(rc EQUAL 0)
      message(FATAL_ERROR "${SOURCE} compiles with ${BAD}: it must be refused")
    endif()
    string(FIND "${err}" "${MESSAGE}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "${SOURCE} is refused with ${BAD}, but without the message '${MESSAGE}':\n${err}")
    endif()
  endif()
endforeach()
message(STATUS "${BAD} refused with '${MESSAGE}'; ${GOOD} accepted")
