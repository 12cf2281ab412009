# Driver of a headless test of the Lex_optimal_chains plugin (cmake -P):
#   cmake -DDEMO=<Polyhedron_3 or CGALlab> -DLEX_RECONSTRUCT=<lex_reconstruct> -DSCRIPT=<test .js> -DDATA=<points_3 dir>
#         -DOUT=<output dir> -DCASE=closed|open|features|errors [-DTIMEOUT=<s>] -P run_demo_test.cmake
# Runs the real demo under xvfb-run with the script test file (JavaScript), then checks what the script
# printed ("RESULT <json>" lines of the demo's stdout) against lex_reconstruct --json
# on the same input (closed, open, features) or against the library's reasons (errors), and that the
# screenshots are real images. Fails (FATAL_ERROR) on any difference.
cmake_minimum_required(VERSION 3.19) # string(JSON)
foreach(var DEMO LEX_RECONSTRUCT SCRIPT DATA OUT CASE)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_demo_test.cmake: -D${var}=... is missing")
  endif()
endforeach()
if(NOT DEFINED TIMEOUT)
  set(TIMEOUT 300)
endif()
# (a missing file would make the demo open a modal message box and wait until the timeout)
foreach(file kitten.xyz b9_training.ply)
  if(NOT EXISTS "${DATA}/${file}")
    message(FATAL_ERROR "${DATA}/${file} not found (CGAL's data: /usr/share/doc/libcgal-dev/data.tar.gz)")
  endif()
endforeach()
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
include("${CMAKE_CURRENT_LIST_DIR}/demo_test_functions.cmake")

# The inputs that the errors test loads: an empty point set, an open polyline near b9_training.
file(WRITE "${OUT}/empty.xyz" "")
file(WRITE "${OUT}/open.polylines.txt"
     "4 596640 243610 80 596750 243610 80 596750 243740 80 596640 243740 80\n")

# lex_reconstruct on the same input: the numbers the demo must reproduce.
function(reference name)
  execute_process(COMMAND "${LEX_RECONSTRUCT}" ${ARGN} --json
                  RESULT_VARIABLE rc OUTPUT_VARIABLE json ERROR_VARIABLE err TIMEOUT ${TIMEOUT})
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "lex_reconstruct ${ARGN} failed (${rc}): ${err}")
  endif()
  set(${name} "${json}" PARENT_SCOPE)
endfunction()
if(CASE STREQUAL "closed")
  reference(expected closed "${DATA}/kitten.xyz" "${OUT}/kitten_cli.off")
  reference(expected_oni closed "${DATA}/oni.ply" "${OUT}/oni_cli.off")
  reference(expected_oni_robust closed "${DATA}/oni.ply" "${OUT}/oni_robust_cli.off" --robust)
elseif(CASE STREQUAL "open")
  reference(expected open "${DATA}/b9_training.ply" "${OUT}/b9_cli.off" --auto-boundary)
  reference(expected_z2 open "${DATA}/b9_training.ply" "${OUT}/b9_z2_cli.off" --auto-boundary --coefficients z2)
elseif(CASE STREQUAL "features")
  reference(expected features "${DATA}/b9_training.ply" "${OUT}/b9_features_cli.off")
  reference(expected_dropped features "${DATA}/b9_training.ply" "${OUT}/b9_features_dropped_cli.off" --drop-largest 1)
endif()

# The demo: the helpers, then the test script.
run_demo(result "${CMAKE_CURRENT_LIST_DIR}/common.js" "${SCRIPT}")

# the mesh of the demo's item against lex_reconstruct's mesh: same size and topology
function(check_mesh demo_json cli_json)
  foreach(key faces vertices components genus closed boundary_edges)
    string(JSON value GET "${cli_json}" ${key})
    check("${demo_json}" ${key} EQUAL "${value}")
  endforeach()
  string(JSON closed GET "${cli_json}" closed)
  check("${demo_json}" is_closed EQUAL "${closed}")
endfunction()

if(CASE STREQUAL "closed")
  string(JSON mesh GET "${result}" mesh)
  check_mesh("${mesh}" "${expected}")
  check("${expected}" faces EQUAL 10420) # kitten, as documented in the manual
  string(JSON oni GET "${result}" oni)
  check_mesh("${oni}" "${expected_oni}")
  string(JSON oni_robust GET "${result}" oni_robust)
  check_mesh("${oni_robust}" "${expected_oni_robust}")
  check("${result}" points_visible EQUAL OFF) # the point set is hidden behind its surface
  check("${result}" actions 0 EQUAL "Closed surface (lexicographic)")
  check("${result}" actions 1 EQUAL "Open surface (lexicographic)")
  check_png(closed_kitten.png)
elseif(CASE STREQUAL "open")
  string(JSON mesh GET "${result}" mesh)
  check_mesh("${mesh}" "${expected}")
  string(JSON mesh_z2 GET "${result}" mesh_z2)
  check_mesh("${mesh_z2}" "${expected_z2}")
  check_png(open_b9_training.png)
elseif(CASE STREQUAL "features")
  # the CLI's JSON has the topology under "mesh" and the elements at the top
  foreach(run mesh:expected dropped:expected_dropped)
    string(REPLACE ":" ";" run "${run}")
    list(GET run 0 key)
    list(GET run 1 variable)
    string(JSON demo_mesh GET "${result}" ${key})
    string(JSON cli_mesh GET "${${variable}}" mesh)
    check_mesh("${demo_mesh}" "${cli_mesh}")
    string(JSON kept GET "${${variable}}" elements)
    string(JSON dropped_elements GET "${${variable}}" dropped_elements)
    math(EXPR kept "${kept} - ${dropped_elements}")
    check("${demo_mesh}" elements EQUAL "${kept}") # one colour per element in the mesh
  endforeach()
  check("${result}" bad item EQUAL -1)
  check("${result}" bad error MATCHES "threshold must be positive")
  string(JSON before GET "${result}" bad entries_before)
  check("${result}" bad entries_after EQUAL "${before}")
  check("${result}" actions 0 EQUAL "Feature-guided reconstruction (lexicographic)")
  check_png(features_b9_training.png)
elseif(CASE STREQUAL "errors")
  # each bad input: no item (-1), the library's reason, and the scene kept as it was
  foreach(name empty no_interior open_polyline cancelled)
    check("${result}" ${name} item EQUAL -1)
    string(JSON before GET "${result}" ${name} entries_before)
    check("${result}" ${name} entries_after EQUAL "${before}")
  endforeach()
  check("${result}" empty error MATCHES "^no input point$")
  check("${result}" no_interior error MATCHES "most persistent void has a persistence of only")
  check("${result}" open_polyline error MATCHES "is not closed")
  check("${result}" cancelled error MATCHES "^cancelled$")
  check("${result}" after_cancel faces EQUAL 10420) # the same run, not cancelled
else()
  message(FATAL_ERROR "unknown CASE ${CASE}")
endif()
message(STATUS "passed: ${CASE}")
