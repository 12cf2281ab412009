# urban_add_program(<name> <object library> <test label>): a command-line program of the
# packages, linked from the object library of its translation unit and Process_group.cpp (the
# processes of one command), with the tests cgal_add_test makes (compilation, and execution with
# the arguments of <name>.cmd of the calling folder when BUILD_TESTING); and, with URBAN_WITH_MPI
# and MPI found, <name>_mpi: the same object library and Process_group.cpp with
# PROCESS_GROUP_WITH_MPI (the work of one command dealt out to MPI ranks), built by ctest before
# the tests that run it (fixture <name>_mpi), its compilation test labelled <test label>.
include_guard(GLOBAL)
set(URBAN_PROCESS_GROUP_SOURCE "${CMAKE_CURRENT_LIST_DIR}/../examples/Lex_optimal_chains/Process_group.cpp")

function(urban_add_program name main_library label)
  add_executable(${name} "${URBAN_PROCESS_GROUP_SOURCE}")
  target_link_libraries(${name} PRIVATE ${main_library})
  if(BUILD_TESTING)
    cgal_add_test(${name})
  else()
    cgal_add_test(${name} NO_EXECUTION)
  endif()
  if(NOT URBAN_WITH_MPI)
    return()
  endif()
  find_package(MPI QUIET COMPONENTS CXX)
  if(NOT MPI_CXX_FOUND)
    message(STATUS "NOTICE: MPI not found (Debian: libopenmpi-dev); ${name}_mpi will not be built")
    return()
  endif()
  add_executable(${name}_mpi "${URBAN_PROCESS_GROUP_SOURCE}")
  target_compile_definitions(${name}_mpi PRIVATE PROCESS_GROUP_WITH_MPI)
  target_link_libraries(${name}_mpi PRIVATE ${main_library} MPI::MPI_CXX)
  if(BUILD_TESTING)
    add_test(NAME compilation_of__${name}_mpi
             COMMAND ${CMAKE_COMMAND} --build ${CMAKE_BINARY_DIR} --target ${name}_mpi --config $<CONFIG>)
    set_tests_properties(compilation_of__${name}_mpi PROPERTIES FIXTURES_SETUP ${name}_mpi LABELS ${label})
  endif()
endfunction()
