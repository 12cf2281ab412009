# One input of the data sweep through every program of the packages (run with cmake -P).
# Arguments: LEX (lex_reconstruct), LOD2 (lod2_reconstruct), CHECKER (check_output_mesh), INPUT,
# WORK, TIME_LIMIT (seconds per run), TILE_SIZES (optional: the input is terrain-like, and
# `lex_reconstruct tiles` runs with each of these tile sizes).
# Each run must end in a mesh that check_output_mesh accepts (CGAL's PMP: a valid oriented
# 2-manifold; closed for the closed surface and the LOD2 solids; one disk for the union of
# the tiles) or in a refusal: exit code 1, one line "<program>: error: ...", no output and no
# partial file. A crash, a time-out, another exit code or a defect of the mesh fails the test.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set(defects "")
set(summary "")

# check(name output options...): the checker's verdict on `output`
function(check name output)
  execute_process(COMMAND "${CHECKER}" "${output}" ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE verdict ERROR_VARIABLE err)
  string(STRIP "${verdict}${err}" verdict)
  if(NOT rc EQUAL 0)
    set(defects "${defects}\n  ${name}: ${verdict}" PARENT_SCOPE)
  endif()
  set(summary "${summary}\n  ${name}: ${verdict}" PARENT_SCOPE)
endfunction()

# run(name output command...): runs the command; on success `json` holds its standard output
# and `succeeded` is true; on a refusal, checks it; anything else is a defect
function(run name output)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT ${TIME_LIMIT})
  set(succeeded FALSE PARENT_SCOPE)
  set(json "${out}" PARENT_SCOPE)
  file(GLOB partial "${WORK}/*partial*" "${WORK}/.*partial*" "${WORK}/*/*partial*" "${WORK}/*/.*partial*")
  string(STRIP "${err}" err)
  list(GET ARGN 0 program)
  get_filename_component(program "${program}" NAME)
  if(partial)
    set(defects "${defects}\n  ${name}: a partial file was left behind: ${partial}" PARENT_SCOPE)
  elseif(rc EQUAL 0)
    if(NOT EXISTS "${output}")
      set(defects "${defects}\n  ${name}: exit code 0 and no output" PARENT_SCOPE)
    else()
      set(succeeded TRUE PARENT_SCOPE)
    endif()
  elseif(rc EQUAL 1)
    string(FIND "${err}" "\n" newline)
    if(EXISTS "${output}")
      set(defects "${defects}\n  ${name}: a refusal left its output behind" PARENT_SCOPE)
    elseif(NOT newline EQUAL -1 OR NOT err MATCHES "^${program}: error: ")
      set(defects "${defects}\n  ${name}: a refusal that is not one line: '${err}'" PARENT_SCOPE)
    else()
      set(summary "${summary}\n  ${name}: refused: ${err}" PARENT_SCOPE)
    endif()
  else()
    set(defects "${defects}\n  ${name}: ${rc} (a crash, a time-out of ${TIME_LIMIT} s, or an unexpected exit code): ${err}" PARENT_SCOPE)
  endif()
endfunction()

# the three surfaces of lex_reconstruct
run(closed "${WORK}/closed.off" "${LEX}" closed "${INPUT}" "${WORK}/closed.off" --json)
if(succeeded)
  check(closed "${WORK}/closed.off" --closed)
endif()
run(open "${WORK}/open.off" "${LEX}" open "${INPUT}" "${WORK}/open.off" --auto-boundary --json)
if(succeeded)
  check(open "${WORK}/open.off")
endif()
run(features "${WORK}/features.off" "${LEX}" features "${INPUT}" "${WORK}/features.off" --json)
if(succeeded)
  # the points where elements of the basis meet, split and said
  string(JSON split GET "${json}" non_manifold_vertices)
  check(features "${WORK}/features.off" --split-points ${split})
endif()
# the tiles of a terrain-like input, and their union
foreach(size IN LISTS TILE_SIZES)
  run(tiles_${size} "${WORK}/tiles_${size}" "${LEX}" tiles "${INPUT}" "${WORK}/tiles_${size}" --tile-size ${size}
      --merged "${WORK}/tiles_${size}.off" --json)
  if(succeeded)
    file(GLOB tiles "${WORK}/tiles_${size}/*.ply")
    if(NOT tiles)
      set(defects "${defects}\n  tiles_${size}: no tile mesh")
    endif()
    foreach(tile IN LISTS tiles)
      get_filename_component(tile_name "${tile}" NAME_WE)
      check(tiles_${size}/${tile_name} "${tile}")
    endforeach()
    check(tiles_${size}/union "${WORK}/tiles_${size}.off" --disk)
  endif()
endforeach()
# the LOD2 model: closed solids
run(lod2 "${WORK}/lod2.off" "${LOD2}" "${INPUT}" "${WORK}/lod2.off" --json)
if(succeeded)
  check(lod2 "${WORK}/lod2.off" --closed)
endif()

message(STATUS "${INPUT}:${summary}")
if(defects)
  message(FATAL_ERROR "${INPUT}:${defects}")
endif()
