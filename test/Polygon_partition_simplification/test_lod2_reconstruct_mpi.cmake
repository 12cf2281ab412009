# lod2_reconstruct_mpi: the buildings of a synthetic classified tile (test_synthetic_city, as
# LAS), dealt out to 2 MPI ranks, give byte for byte the CityJSON (.city.json and .city.jsonl)
# of lod2_reconstruct in one process, buildings found by connectivity and given by footprints;
# every rank models some buildings and the counts are those of one process. Bad input gives one
# line of ours (mpirun adds its own banner), an exit code other than 0 and no output, and a
# scene is refused on more than one rank.
#   cmake -DPROGRAM=lod2_reconstruct -DMPI_PROGRAM=lod2_reconstruct_mpi -DMPIEXEC=mpirun
#         -DCITY_WRITER=test_synthetic_city -DDATA=<CGAL data> -DWORK=<scratch directory>
#         -P test_lod2_reconstruct_mpi.cmake
cmake_minimum_required(VERSION 3.19) # string(JSON)
include("${CMAKE_CURRENT_LIST_DIR}/../../cmake/Urban_cli_test_functions.cmake")
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
# mpirun as root (CI containers) and with more ranks than cores
set(mpirun "${MPIEXEC}" --allow-run-as-root --oversubscribe)

execute_process(COMMAND "${CITY_WRITER}" 12 "${WORK}/city.las" "${WORK}/city.geojson" RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the synthetic tile: exit code ${rc}: ${err}")
endif()

# run(name json_variable command...): the command, which must succeed; its JSON line
function(run name json_variable)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE json ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name}: exit code ${rc}: ${err}")
  endif()
  set(${json_variable} "${json}" PARENT_SCOPE)
endfunction()

# the outputs of one process in one/, those of 2 ranks in two/
file(MAKE_DIRECTORY "${WORK}/one" "${WORK}/two")
foreach(output clusters.city.json clusters.city.jsonl footprints.city.json)
  set(options --threads 1 --json)
  if(output MATCHES "footprints")
    list(APPEND options --footprints "${WORK}/city.geojson")
  endif()
  run("one process, ${output}" one "${PROGRAM}" "${WORK}/city.las" "${WORK}/one/${output}" ${options})
  run("2 ranks, ${output}" two ${mpirun} -np 2 "${MPI_PROGRAM}" "${WORK}/city.las" "${WORK}/two/${output}" ${options})
  execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files "${WORK}/one/${output}" "${WORK}/two/${output}"
                  RESULT_VARIABLE different)
  if(NOT different EQUAL 0)
    message(FATAL_ERROR "${output}: the output of 2 ranks differs from that of one process")
  endif()
  # the JSON line of the first rank only, with the counts of one process
  foreach(key buildings buildings_valid buildings_lod12_fallback points building_points ground_points)
    string(JSON a GET "${one}" ${key})
    string(JSON b GET "${two}" ${key})
    if(NOT a EQUAL b)
      message(FATAL_ERROR "${output}: ${key} is ${b} on 2 ranks, ${a} in one process: ${two}")
    endif()
  endforeach()
  string(JSON ranks GET "${two}" ranks)
  string(JSON buildings GET "${two}" buildings)
  string(JSON first GET "${two}" buildings_per_rank 0)
  string(JSON second GET "${two}" buildings_per_rank 1)
  math(EXPR sum "${first} + ${second}")
  if(NOT ranks EQUAL 2 OR first LESS 1 OR second LESS 1 OR NOT sum EQUAL buildings OR buildings LESS 10)
    message(FATAL_ERROR "${output}: expected at least 10 buildings shared by 2 ranks: ${two}")
  endif()
  message(STATUS "${output}: ${buildings} buildings (${first} and ${second} per rank), byte for byte those of one process")
endforeach()

# bad input: exactly one line of ours, whatever the number of ranks, and nothing written
function(expect_lod2_mpi_failure name reason output)
  expect_mpi_failure(${name} "${reason}" lod2_reconstruct "${output}" ${mpirun} -np 2 "${MPI_PROGRAM}" ${ARGN} "${output}")
endfunction()
expect_lod2_mpi_failure(no_building_class "no point of a building class" "${WORK}/no_class.city.json" "${WORK}/city.las" --classes 2:7)
expect_lod2_mpi_failure(missing_input "cannot read" "${WORK}/missing.city.json" "${WORK}/missing.ply")
expect_lod2_mpi_failure(scene "only city tiles" "${WORK}/scene.off" "${DATA}/points_3/building.ply" --planes segment_index)
