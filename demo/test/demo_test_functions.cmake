# Functions shared by the drivers of the headless demo tests (run_demo_test.cmake,
# run_partition_demo_test.cmake), included after they have checked DEMO, OUT and TIMEOUT.

find_program(XVFB_RUN xvfb-run)
if(NOT XVFB_RUN)
  message(FATAL_ERROR "xvfb-run not found: apt-get install xvfb xauth")
endif()

# run_demo(<result variable> <script>...): runs the demo with the scripts (after a first
# argument that sets DATA and OUT in them) and sets the variable to the JSON of the
# "RESULT <json>" line it printed (print() writes "QtScript: <text>" in the Polyhedron demo,
# "Script message: <text>" in CGAL Lab); fails when the demo fails, prints no such line, or
# the result is {"failure": ...}. The demo's settings go to a fresh XDG_CONFIG_HOME (no user's
# settings or plugin blacklist); it is killed after TIMEOUT seconds (a script that fails before
# main_window.quit() would leave the demo waiting for events).
function(run_demo result_variable)
  file(MAKE_DIRECTORY "${OUT}/config")
  execute_process(
    COMMAND "${CMAKE_COMMAND}" -E env "XDG_CONFIG_HOME=${OUT}/config" "LIBGL_ALWAYS_SOFTWARE=1"
            "${XVFB_RUN}" -a -s "-screen 0 1280x1024x24"
            "${DEMO}" --no-autostart "javascript:var DATA = '${DATA}'; var OUT = '${OUT}';" ${ARGN}
    WORKING_DIRECTORY "${OUT}"
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT ${TIMEOUT})
  file(WRITE "${OUT}/demo_stdout.txt" "${out}")
  file(WRITE "${OUT}/demo_stderr.txt" "${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the demo failed (${rc}); stdout:\n${out}\nstderr:\n${err}")
  endif()
  string(REGEX MATCH "(QtScript|Script message): RESULT ([^\n]*)" line "${out}")
  if(NOT line)
    message(FATAL_ERROR "the script printed no RESULT line; stdout:\n${out}\nstderr:\n${err}")
  endif()
  set(result "${CMAKE_MATCH_2}")
  message(STATUS "demo: ${result}")
  string(JSON failure ERROR_VARIABLE no_failure GET "${result}" "failure")
  if(NOT no_failure)
    message(FATAL_ERROR "the script failed: ${failure}\nstderr:\n${err}")
  endif()
  set(${result_variable} "${result}" PARENT_SCOPE)
endfunction()

# check(<json> <path...> EQUAL|MATCHES <expected>)
function(check json)
  set(args ${ARGN})
  list(POP_BACK args expected)
  list(POP_BACK args op)
  string(JSON value ERROR_VARIABLE error GET "${json}" ${args})
  if(error)
    message(FATAL_ERROR "no ${args} in ${json}")
  endif()
  if(op STREQUAL "EQUAL" AND NOT value STREQUAL expected)
    message(FATAL_ERROR "${args}: the demo gives ${value}, expected ${expected}")
  elseif(op STREQUAL "MATCHES" AND NOT value MATCHES "${expected}")
    message(FATAL_ERROR "${args}: '${value}' does not match '${expected}'")
  endif()
endfunction()

# a screenshot the script saved: a PNG file (saveSnapshot refuses a blank image)
function(check_png name)
  if(NOT EXISTS "${OUT}/${name}")
    message(FATAL_ERROR "no screenshot ${OUT}/${name}")
  endif()
  file(READ "${OUT}/${name}" signature LIMIT 8 HEX)
  if(NOT signature STREQUAL "89504e470d0a1a0a")
    message(FATAL_ERROR "${OUT}/${name} is not a PNG file")
  endif()
endfunction()
