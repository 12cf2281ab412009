# The targets of the two header-only packages and the CGAL data they are tested on, shared by
# the top-level CMakeLists.txt and by each test/<Pkg>/ folder configured on its own
# (cmake -S test/<Pkg>), as CGAL's test suite configures its test folders.
include_guard(GLOBAL)

set(URBAN_PACKAGES_ROOT "${CMAKE_CURRENT_LIST_DIR}/.." CACHE INTERNAL "Root of the two packages")
if(NOT CMAKE_CXX_STANDARD)
  set(CMAKE_CXX_STANDARD 17)
  set(CMAKE_CXX_STANDARD_REQUIRED ON)
endif()
option(LEX_WITH_TBB "Use TBB for the parallel Delaunay triangulation when found" ON)

# Release by default; the packages' code is warning-free with -Wall -Wextra (g++ 12); ccache
# when present (build times matter on two cores).
if(NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type" FORCE)
endif()
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  add_compile_options(-Wall -Wextra)
endif()
# Paths below the checkout are hashed relative to it (CCACHE_BASEDIR), so that a clean clone
# elsewhere, as CI makes, finds the objects of an earlier one.
find_program(CCACHE_PROGRAM ccache)
if(CCACHE_PROGRAM)
  get_filename_component(urban_checkout "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)
  set(CMAKE_CXX_COMPILER_LAUNCHER "${CMAKE_COMMAND}" -E env "CCACHE_BASEDIR=${urban_checkout}" "${CCACHE_PROGRAM}")
endif()

include(${CMAKE_CURRENT_LIST_DIR}/Urban_sanitizers.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/Urban_programs.cmake)

# shared with the folders configured on their own
option(URBAN_WITH_MPI "Build lex_reconstruct_mpi and lod2_reconstruct_mpi (work dealt out to MPI ranks) when MPI is found" ON)

# A test folder configured on its own (cmake -S test/<Pkg>), as CGAL's test suite does: the
# tests are built and ctest runs them.
if(NOT URBAN_TOP_LEVEL)
  set(BUILD_TESTING ON CACHE BOOL "Build the tests (CGAL test-suite layout, run by ctest)")
  enable_testing()
endif()

# CGAL 5.5 or 6. CGAL 6 names its tests "compilation of  <target>" (with spaces), which needs
# CMake's policy CMP0110 (3.19) in the folders that add tests: the folders below the top level
# take it from this default; a test folder configured on its own sets it itself.
set(CMAKE_POLICY_DEFAULT_CMP0110 NEW)
find_package(CGAL 5.5 REQUIRED)
message(STATUS "CGAL ${CGAL_VERSION}: ${CGAL_INCLUDE_DIRS}")
include(${CMAKE_CURRENT_LIST_DIR}/Urban_system_CGAL_stubs.cmake)
find_package(Eigen3 3.3 QUIET)
if(EIGEN3_FOUND OR TARGET Eigen3::Eigen)
  include(CGAL_Eigen3_support)
endif()
if(LEX_WITH_TBB)
  find_package(TBB QUIET)
  include(CGAL_TBB_support)
endif()

if(NOT TARGET Lex_optimal_chains)
  add_library(Lex_optimal_chains INTERFACE)
  target_include_directories(Lex_optimal_chains INTERFACE "${URBAN_PACKAGES_ROOT}/Lex_optimal_chains/include")
  target_link_libraries(Lex_optimal_chains INTERFACE CGAL::CGAL)
  if(URBAN_SYSTEM_CGAL_STUBS)
    target_include_directories(Lex_optimal_chains INTERFACE "${URBAN_SYSTEM_CGAL_STUBS}")
  endif()
  if(TARGET CGAL::TBB_support)
    target_link_libraries(Lex_optimal_chains INTERFACE CGAL::TBB_support)
  endif()
  # the robust closed surface mode smooths the points by jet fitting, which needs Eigen
  if(TARGET CGAL::Eigen3_support)
    target_link_libraries(Lex_optimal_chains INTERFACE CGAL::Eigen3_support)
  endif()
endif()
if(NOT TARGET Polygon_partition_simplification)
  add_library(Polygon_partition_simplification INTERFACE)
  target_include_directories(Polygon_partition_simplification INTERFACE
    "${URBAN_PACKAGES_ROOT}/Polygon_partition_simplification/include")
  target_link_libraries(Polygon_partition_simplification INTERFACE CGAL::CGAL)
  if(URBAN_SYSTEM_CGAL_STUBS)
    target_include_directories(Polygon_partition_simplification INTERFACE "${URBAN_SYSTEM_CGAL_STUBS}")
  endif()
  # the LOD2 pipeline: normals (jet fitting) and plane fitting need Eigen
  if(TARGET CGAL::Eigen3_support)
    target_link_libraries(Polygon_partition_simplification INTERFACE CGAL::Eigen3_support)
  endif()
  # the city-scale LOD2 reconstruction models its buildings in parallel
  if(TARGET CGAL::TBB_support)
    target_link_libraries(Polygon_partition_simplification INTERFACE CGAL::TBB_support)
  endif()
  # Line_partition_2 checks and lists its cells with CGAL's Arrangement_2
  urban_no_vptr_check(Polygon_partition_simplification)
endif()

# Real data shipped by Debian's libcgal-demo, unpacked in the build tree (never committed).
set(URBAN_CGAL_DATA_ARCHIVE "/usr/share/doc/libcgal-dev/data.tar.gz" CACHE FILEPATH "CGAL data archive")
set(URBAN_CGAL_DATA_DIR "${CMAKE_BINARY_DIR}/cgal-data/data" CACHE PATH "Unpacked CGAL data")
if(NOT EXISTS "${URBAN_CGAL_DATA_DIR}/points_3/kitten.xyz" AND EXISTS "${URBAN_CGAL_DATA_ARCHIVE}")
  message(STATUS "Unpacking ${URBAN_CGAL_DATA_ARCHIVE}")
  file(ARCHIVE_EXTRACT INPUT "${URBAN_CGAL_DATA_ARCHIVE}" DESTINATION "${CMAKE_BINARY_DIR}/cgal-data")
endif()
