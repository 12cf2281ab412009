# The checks of bad input shared by the tests of the command-line programs (run with cmake -P).

# expect_cli_failure(name output command...): runs the command and checks what a bad input must
# give: an exit code other than 0, no file `output`, no partial file left in WORK, and a reason
# of one line that starts with "<program>: error: " (the program named by the command's first
# word). The reason is left in `last_error` in the caller's scope.
function(expect_cli_failure name output)
  list(GET ARGN 0 program)
  get_filename_component(program_name "${program}" NAME)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
  if(rc EQUAL 0)
    message(FATAL_ERROR "${name}: expected a failure, got exit code 0")
  endif()
  if(EXISTS "${output}")
    message(FATAL_ERROR "${name}: an output file was left behind")
  endif()
  file(GLOB partial "${WORK}/*partial*" "${WORK}/.*partial*")
  if(partial)
    message(FATAL_ERROR "${name}: a partial file was left behind: ${partial}")
  endif()
  string(STRIP "${err}" err)
  string(FIND "${err}" "\n" newline)
  if(NOT newline EQUAL -1 OR NOT err MATCHES "^${program_name}: error: ")
    message(FATAL_ERROR "${name}: the reason is not one line: '${err}'")
  endif()
  message(STATUS "${name}: ${err}")
  set(last_error "${err}" PARENT_SCOPE)
endfunction()

# expect_json_keys(name json key...): the JSON line `json` has every key
function(expect_json_keys name json)
  foreach(key ${ARGN})
    string(JSON value ERROR_VARIABLE missing GET "${json}" ${key})
    if(missing)
      message(FATAL_ERROR "${name}: the JSON line has no '${key}': ${json}")
    endif()
  endforeach()
endfunction()

# expect_mpi_failure(name reason program_name outputs command...): as expect_cli_failure, for a
# command run by mpirun, whose standard error also holds the launcher's own messages: exactly one
# line there starts with "<program_name>: error: " and matches `reason`, and none of the files or
# folders of the list `outputs` (nor a partial file in WORK) exists.
function(expect_mpi_failure name reason program_name outputs)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
  if(rc EQUAL 0)
    message(FATAL_ERROR "${name}: expected a failure, got exit code 0")
  endif()
  string(REGEX MATCHALL "${program_name}: error: [^\n]*" ours "${err}")
  list(LENGTH ours lines)
  if(NOT lines EQUAL 1 OR NOT ours MATCHES "${reason}")
    message(FATAL_ERROR "${name}: not one line with '${reason}': '${err}'")
  endif()
  file(GLOB partial "${WORK}/*partial*" "${WORK}/.*partial*")
  foreach(output IN LISTS outputs)
    if(EXISTS "${output}" OR partial)
      message(FATAL_ERROR "${name}: output left behind")
    endif()
  endforeach()
  message(STATUS "${name}: ${ours}")
endfunction()
