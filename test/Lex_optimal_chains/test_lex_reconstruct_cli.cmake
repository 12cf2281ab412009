# Runs lex_reconstruct on good and bad input. Arguments: PROGRAM, DATA, WORK.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

include("${CMAKE_CURRENT_LIST_DIR}/../../cmake/Urban_cli_test_functions.cmake")

# expect_failure(name subcommand input [options...]): exit code 1, one line, no output
macro(expect_failure name subcommand input)
  expect_cli_failure(${name} "${WORK}/${name}.off" "${PROGRAM}" ${subcommand} "${input}" "${WORK}/${name}.off" ${ARGN})
endmacro()

# expect_failure_because(name reason subcommand input [options...]): as expect_failure, with a
# reason that matches the regular expression `reason`
function(expect_failure_because name reason subcommand input)
  expect_failure(${name} ${subcommand} "${input}" ${ARGN})
  if(NOT last_error MATCHES "${reason}")
    message(FATAL_ERROR "${name}: not the reason expected: '${last_error}'")
  endif()
endfunction()

# expect_points(name input count): the closed surface of `input` is made from `count` points
function(expect_points name input count)
  execute_process(COMMAND "${PROGRAM}" closed "${input}" "${WORK}/${name}.off" --json
                  RESULT_VARIABLE rc OUTPUT_VARIABLE json ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name}: exit code ${rc}: ${err}")
  endif()
  string(JSON points GET "${json}" points)
  if(NOT points EQUAL count)
    message(FATAL_ERROR "${name}: ${points} points read, ${count} expected")
  endif()
endfunction()

file(WRITE "${WORK}/empty.xyz" "")
file(WRITE "${WORK}/three.xyz" "0 0 0\n1 0 0\n0 1 0\n")
file(WRITE "${WORK}/plane.xyz" "0 0 0\n1 0 0\n0 1 0\n1 1 0\n2 3 0\n")
file(WRITE "${WORK}/same.xyz" "1 1 1\n1 1 1\n1 1 1\n1 1 1\n1 1 1\n")
file(WRITE "${WORK}/garbage.xyz" "hello world\n")
expect_failure(empty closed "${WORK}/empty.xyz")
expect_failure(three closed "${WORK}/three.xyz")
expect_failure(plane closed "${WORK}/plane.xyz")
expect_failure(duplicates closed "${WORK}/same.xyz")
expect_failure(garbage closed "${WORK}/garbage.xyz")
expect_failure(missing closed "${WORK}/does_not_exist.xyz")
expect_failure(outside closed "${DATA}/points_3/kitten.xyz" --interior 100,100,100)
expect_failure(bad_point closed "${DATA}/points_3/kitten.xyz" --interior 1,2)

# an existing file is not overwritten by a failed run
file(WRITE "${WORK}/keep.off" "precious")
execute_process(COMMAND "${PROGRAM}" closed "${WORK}/empty.xyz" "${WORK}/keep.off" RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
file(READ "${WORK}/keep.off" kept)
if(rc EQUAL 0 OR NOT kept STREQUAL "precious")
  message(FATAL_ERROR "a failed run overwrote an existing output")
endif()

# good input: a closed mesh and one JSON line
execute_process(COMMAND "${PROGRAM}" closed "${DATA}/points_3/kitten.xyz" "${WORK}/kitten.ply" --json
                RESULT_VARIABLE rc OUTPUT_VARIABLE json)
if(NOT rc EQUAL 0 OR NOT EXISTS "${WORK}/kitten.ply")
  message(FATAL_ERROR "kitten: exit code ${rc}")
endif()
expect_json_keys("kitten" "${json}" delaunay_s order_s cut_s resolution_s mesh_s write_s output_s
                 total_s peak_rss_mb vertices faces components boundary_edges non_manifold_vertices
                 non_manifold_edges resolved_non_manifold_vertices resolution_changed_triangles
                 closed genus)
string(JSON closed GET "${json}" closed)
string(JSON components GET "${json}" components)
if(NOT closed STREQUAL "ON" OR NOT components EQUAL 1)
  message(FATAL_ERROR "kitten: not one closed component: ${json}")
endif()
message(STATUS "kitten: ${json}")
# .ply is written binary, unless --ascii
file(READ "${WORK}/kitten.ply" kitten_header LIMIT 60)
execute_process(COMMAND "${PROGRAM}" closed "${DATA}/points_3/kitten.xyz" "${WORK}/kitten_ascii.ply" --ascii RESULT_VARIABLE rc)
file(READ "${WORK}/kitten_ascii.ply" kitten_ascii_header LIMIT 60)
if(NOT kitten_header MATCHES "format binary_little_endian" OR NOT rc EQUAL 0 OR NOT kitten_ascii_header MATCHES "format ascii")
  message(FATAL_ERROR "kitten: .ply not binary by default, or not text with --ascii")
endif()
# the binary file is read back by CGAL's reader: as many points as the mesh has vertices
string(JSON kitten_vertices GET "${json}" vertices)
expect_points(kitten_binary_read_back "${WORK}/kitten.ply" ${kitten_vertices})

# kitten.xyz as OFF and PLY files whose header declares 5,000 of its 5,210 points: CGAL's
# readers stop after 5,000 and would ignore the rest; lex_reconstruct refuses the file. With
# the right count it reconstructs it.
file(STRINGS "${DATA}/points_3/kitten.xyz" kitten_lines)
set(kitten_points "")
foreach(l IN LISTS kitten_lines)
  string(REGEX MATCH "^[ \t]*[^ \t]+[ \t]+[^ \t]+[ \t]+[^ \t]+" xyz "${l}")
  string(APPEND kitten_points "${xyz}\n")
endforeach()
list(LENGTH kitten_lines kitten_count)
set(ply_header "ply\nformat ascii 1.0\nelement vertex @N@\nproperty double x\nproperty double y\nproperty double z\nend_header\n")
foreach(n 5000 ${kitten_count})
  file(WRITE "${WORK}/kitten_${n}.off" "OFF\n${n} 0 0\n${kitten_points}")
  string(REPLACE "@N@" "${n}" header "${ply_header}")
  file(WRITE "${WORK}/kitten_${n}.ply" "${header}${kitten_points}")
endforeach()
foreach(ext off ply)
  expect_failure_because(short_header_${ext} "holds more records than its header declares" closed
                         "${WORK}/kitten_5000.${ext}")
  expect_points(full_header_${ext} "${WORK}/kitten_${kitten_count}.${ext}" ${kitten_count})
endforeach()

# spheres.ply (binary, 5,969 points of 48 bytes) with a header that declares 5,900 of them:
# the size of the data tells that the file holds more than declared. The header is rewritten
# with the shell's coreutils (CMake cannot write binary files). The file as it is passes.
execute_process(COMMAND sh -c "n=$(head -n 4 \"$1\" | wc -c) && { head -n 3 \"$1\"; echo 'element vertex 5900'; tail -c +$((n + 1)) \"$1\"; } > \"$2\""
                        sh "${DATA}/points_3/spheres.ply" "${WORK}/spheres_5900.ply" RESULT_VARIABLE rc)
file(READ "${WORK}/spheres_5900.ply" spheres_header LIMIT 120)
if(NOT rc EQUAL 0 OR NOT spheres_header MATCHES "element vertex 5900\nproperty double x")
  message(FATAL_ERROR "could not write spheres.ply with a short header (exit code ${rc})")
endif()
expect_failure_because(short_header_binary_ply "holds more data than its header declares" closed
                       "${WORK}/spheres_5900.ply")
expect_points(spheres "${DATA}/points_3/spheres.ply" 5969)

# oni.ply: its most persistent void (2.6) is below 4, but stands out from the others (the
# second has 1.34): it is taken as the interior, one closed surface through most of the
# points. With a fixed --min-persistence above it, it is refused. A partial scan (hippo1.ply)
# has no void that stands out: refused with the reason.
execute_process(COMMAND "${PROGRAM}" closed "${DATA}/points_3/oni.ply" "${WORK}/oni.off" --json
                RESULT_VARIABLE rc OUTPUT_VARIABLE json)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "oni: exit code ${rc}")
endif()
string(JSON closed GET "${json}" closed)
string(JSON components GET "${json}" components)
string(JSON vertices GET "${json}" vertices)
string(JSON points GET "${json}" points)
string(JSON persistence GET "${json}" interior_persistence)
string(JSON runner_up GET "${json}" runner_up_persistence)
math(EXPR most "${points} * 3 / 4")
if(NOT closed STREQUAL "ON" OR NOT components EQUAL 1 OR vertices LESS most OR persistence GREATER 4
   OR NOT runner_up GREATER 1)
  message(FATAL_ERROR "oni: not one closed surface through most of the points: ${json}")
endif()
expect_failure_because(oni_fixed_threshold "persistence of only 2.6[0-9]* \\(< 3\\)" closed "${DATA}/points_3/oni.ply"
                       --min-persistence 3)
expect_failure_because(partial_scan "persistence of only 1.0[0-9]* \\(< 2\\)" closed "${DATA}/points_3/hippo1.ply")

# --robust: the points are smoothed, and the JSON says how
execute_process(COMMAND "${PROGRAM}" closed "${DATA}/points_3/oni.ply" "${WORK}/oni_robust.off" --robust --json
                RESULT_VARIABLE rc OUTPUT_VARIABLE json)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "oni --robust: exit code ${rc}")
endif()
expect_json_keys("oni --robust" "${json}" robust scale smoothing_passes noise_estimate
                 average_spacing smoothing_s points_on_surface)
string(JSON robust GET "${json}" robust)
string(JSON scale GET "${json}" scale)
string(JSON noise GET "${json}" noise_estimate)
string(JSON spacing GET "${json}" average_spacing)
string(JSON closed GET "${json}" closed)
if(NOT robust STREQUAL "ON" OR scale LESS 24 OR NOT noise GREATER 0 OR NOT noise LESS spacing OR NOT closed STREQUAL "ON")
  message(FATAL_ERROR "oni --robust: ${json}")
endif()
execute_process(COMMAND "${PROGRAM}" closed "${DATA}/points_3/oni.ply" "${WORK}/oni_k48.off" --robust
                        --smoothing-neighbors 48 --json RESULT_VARIABLE rc OUTPUT_VARIABLE json)
string(JSON scale GET "${json}" scale)
if(NOT rc EQUAL 0 OR NOT scale EQUAL 48)
  message(FATAL_ERROR "oni --robust --smoothing-neighbors 48: exit code ${rc}, ${json}")
endif()
# blobby.xyz smoothed: two pockets (8.3 and 4.3), the first above 4 but not standing out
expect_failure_because(blobby_robust "does not stand out" closed "${DATA}/points_3/blobby.xyz" --robust)
expect_failure_because(interior_outside_smoothed "as the robust mode smoothed them" closed "${DATA}/points_3/blobby.xyz"
                       --robust --interior 0.1,0,0)
expect_failure(neighbors_without_robust closed "${DATA}/points_3/oni.ply" --smoothing-neighbors 30)
expect_failure(neighbors_too_few closed "${DATA}/points_3/oni.ply" --robust --smoothing-neighbors 3)
# bad option values and a missing output directory: the same one-line contract
expect_failure(min_persistence_zero closed "${DATA}/points_3/oni.ply" --min-persistence 0)
expect_failure(min_persistence_nan closed "${DATA}/points_3/oni.ply" --min-persistence nan)
expect_failure(threads_zero closed "${DATA}/points_3/kitten.xyz" --threads 0)
expect_failure(unknown_option closed "${DATA}/points_3/kitten.xyz" --bogus)
execute_process(COMMAND "${PROGRAM}" closed "${DATA}/points_3/kitten.xyz" "${WORK}/no_such_directory/k.off"
                RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
string(STRIP "${err}" err)
if(NOT rc EQUAL 1 OR NOT err MATCHES "^lex_reconstruct: error: cannot write [^\n]*$")
  message(FATAL_ERROR "missing output directory: exit code ${rc}, '${err}'")
endif()

# ----- open surfaces -----
file(WRITE "${WORK}/open_square.polylines" "4 -1 -1 0 2 -1 0 2 2 0 -1 2 0\n")
file(WRITE "${WORK}/eight.polylines" "5 -1 -1 0 2 2 0 2 -1 0 -1 2 0 -1 -1 0\n")
file(WRITE "${WORK}/far.polylines" "5 1000 0 0 1001 0 0 1001 1 0 1000 1 0 1000 0 0\n")
file(WRITE "${WORK}/short.polylines" "5 -1 -1 0 2 -1 0 2 2\n")
file(WRITE "${WORK}/nan.polylines" "5 -1 -1 0 2 -1 nan 2 2 0 -1 2 0 -1 -1 0\n")
expect_failure(open_empty open "${WORK}/empty.xyz" --auto-boundary)
expect_failure(open_polyline open "${DATA}/points_3/b9_training.ply" --boundary "${WORK}/open_square.polylines")
expect_failure(open_self_intersecting open "${DATA}/points_3/b9_training.ply" --boundary "${WORK}/eight.polylines")
expect_failure(open_far open "${DATA}/points_3/b9_training.ply" --boundary "${WORK}/far.polylines")
expect_failure(open_bad_file open "${DATA}/points_3/b9_training.ply" --boundary "${WORK}/short.polylines")
expect_failure(open_nan_boundary open "${DATA}/points_3/b9_training.ply" --boundary "${WORK}/nan.polylines")
expect_failure(open_no_file open "${DATA}/points_3/b9_training.ply" --boundary "${WORK}/none.polylines")
expect_failure(open_coefficients open "${DATA}/points_3/b9_training.ply" --auto-boundary --coefficients r)
# a polygon through the cloud of kitten.xyz (its edges are not Delaunay edges)
file(WRITE "${WORK}/through.polylines" "5 -0.3 -0.3 0 0.3 -0.3 0 0.3 0.3 0 -0.3 0.3 0 -0.3 -0.3 0\n")
expect_failure(open_not_delaunay open "${DATA}/points_3/kitten.xyz" --boundary "${WORK}/through.polylines")

# aerial LiDAR with the automatic boundary: one oriented open surface, the skirt dropped
foreach(field q z2)
  execute_process(COMMAND "${PROGRAM}" open "${DATA}/points_3/b9_training.ply" "${WORK}/b9_${field}.off"
                          --auto-boundary --coefficients ${field} --json
                  RESULT_VARIABLE rc OUTPUT_VARIABLE json)
  if(NOT rc EQUAL 0 OR NOT EXISTS "${WORK}/b9_${field}.off")
    message(FATAL_ERROR "b9_training (${field}): exit code ${rc}")
  endif()
  expect_json_keys("b9_training" "${json}" delaunay_s order_s representative_s optimal_chain_s
                   resolution_s mesh_s write_s output_s total_s peak_rss_mb vertices faces
                   components boundary_edges non_manifold_vertices non_manifold_edges
                   resolved_non_manifold_vertices resolution_changed_triangles closed genus)
  string(JSON closed GET "${json}" closed)
  string(JSON components GET "${json}" components)
  string(JSON faces GET "${json}" faces)
  string(JSON dropped GET "${json}" dropped_triangles)
  string(JSON loops GET "${json}" boundary_loops)
  string(JSON split GET "${json}" non_manifold_edges)
  if(closed STREQUAL "ON" OR NOT components EQUAL 1 OR faces LESS 20000 OR dropped EQUAL 0)
    message(FATAL_ERROR "b9_training (${field}): not one open surface without its skirt: ${json}")
  endif()
  # one disk: the non-manifold edges of the optimum are resolved, not split into holes
  if(NOT loops EQUAL 1 OR NOT split EQUAL 0)
    message(FATAL_ERROR "b9_training (${field}): not one boundary loop without split edges: ${json}")
  endif()
  message(STATUS "b9_training (${field}): ${json}")
endforeach()
# --keep-non-manifold: the optimum as it is, its non-manifold edges split (holes in the terrain)
execute_process(COMMAND "${PROGRAM}" open "${DATA}/points_3/b9_training.ply" "${WORK}/b9_raw.off" --auto-boundary
                        --keep-non-manifold --json
                RESULT_VARIABLE rc OUTPUT_VARIABLE json)
string(JSON loops GET "${json}" boundary_loops)
string(JSON split GET "${json}" non_manifold_edges)
string(JSON resolved GET "${json}" resolved_non_manifold_vertices)
if(NOT rc EQUAL 0 OR loops LESS 2 OR split EQUAL 0 OR NOT resolved EQUAL 0)
  message(FATAL_ERROR "b9_training --keep-non-manifold: the optimum is not kept as it is: ${json}")
endif()

# ----- features: the critical basis around sharp features -----
set(fandisk "${DATA}/meshes/fandisk.off")
execute_process(COMMAND "${PROGRAM}" features "${fandisk}" "${WORK}/fandisk_elements.ply" --json
                RESULT_VARIABLE rc OUTPUT_VARIABLE json ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "features fandisk: exit code ${rc}: ${err}")
endif()
expect_json_keys("features fandisk" "${json}" points feature_points subcomplex_simplices cycles elements faces
                 non_manifold_vertices non_manifold_edges delaunay_s feature_s subcomplex_s chains_s basis_s mesh_s total_s)
string(JSON cycles GET "${json}" cycles)
string(JSON elements GET "${json}" elements)
string(JSON faces GET "${json}" faces)
if(cycles LESS 5 OR NOT elements EQUAL cycles OR faces LESS 5000)
  message(FATAL_ERROR "features fandisk: not a surface in several elements: ${json}")
endif()
file(READ "${WORK}/fandisk_elements.ply" header LIMIT 400)
if(NOT header MATCHES "property int element")
  message(FATAL_ERROR "features fandisk: the PLY file has no element property: ${header}")
endif()
# the largest element dropped: fewer faces
math(EXPR all_but_one "${elements} - 1")
execute_process(COMMAND "${PROGRAM}" features "${fandisk}" "${WORK}/fandisk_dropped.off" --drop-largest 1 --json
                RESULT_VARIABLE rc OUTPUT_VARIABLE json_dropped ERROR_VARIABLE err)
string(JSON faces_dropped GET "${json_dropped}" faces)
if(NOT rc EQUAL 0 OR NOT faces_dropped LESS faces)
  message(FATAL_ERROR "features fandisk --drop-largest 1: ${rc} ${err} ${json_dropped}")
endif()
message(STATUS "features fandisk: ${elements} elements, ${faces} faces; ${faces_dropped} without the largest")
# --borders: fandisk's vertices sample a closed surface, so few border points (anisotropic
# triangles leave some gaps)
execute_process(COMMAND "${PROGRAM}" features "${fandisk}" "${WORK}/fandisk_borders.off" --borders --json
                RESULT_VARIABLE rc OUTPUT_VARIABLE json_borders ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "features fandisk --borders: ${rc} ${err}")
endif()
string(JSON border_points GET "${json_borders}" border_points)
string(JSON points GET "${json_borders}" points)
string(JSON features_with_borders GET "${json_borders}" feature_points)
string(JSON features_without GET "${json}" feature_points)
math(EXPR border_limit "${points} / 20")
if(border_points GREATER border_limit OR border_points EQUAL 0 OR NOT features_with_borders GREATER features_without)
  message(FATAL_ERROR "features fandisk --borders: ${border_points} border points of ${points} on a closed surface, "
                      "${features_with_borders} feature points against ${features_without} without")
endif()
message(STATUS "features fandisk --borders: ${border_points} border points of ${points}")
expect_failure_because(features_no_cycle "no cycle" features "${fandisk}" --offset 0.000001)
expect_failure_because(features_drop_all "dropped" features "${fandisk}" --drop-largest 1000)
expect_failure_because(features_threshold "threshold" features "${fandisk}" --threshold -1)
expect_failure_because(features_missing "cannot" features "${WORK}/missing.xyz")

# ----- tiles: one mesh per tile, their union welded at the seams -----
# bad input: one line, exit code 1, no tile directory and no merged mesh
function(expect_tiles_failure name reason)
  expect_cli_failure(${name} "${WORK}/${name}_dir" "${PROGRAM}" tiles ${ARGN})
  if(EXISTS "${WORK}/${name}_merged.off")
    message(FATAL_ERROR "${name}: a merged mesh was left behind")
  endif()
  if(NOT last_error MATCHES "${reason}")
    message(FATAL_ERROR "${name}: not the reason expected: '${last_error}'")
  endif()
endfunction()
set(b9 "${DATA}/points_3/b9_training.ply")
expect_tiles_failure(tiles_zero "positive" "${b9}" "${WORK}/tiles_zero_dir" --tile-size 0 --merged "${WORK}/tiles_zero_merged.off")
expect_tiles_failure(tiles_negative "positive" "${b9}" "${WORK}/tiles_negative_dir" --tile-size -5)
expect_tiles_failure(tiles_too_large "not smaller than the cloud" "${b9}" "${WORK}/tiles_too_large_dir" --tile-size 1000
                     --merged "${WORK}/tiles_too_large_merged.off")
expect_tiles_failure(tiles_spacing "seam spacing" "${b9}" "${WORK}/tiles_spacing_dir" --tile-size 40 --seam-spacing 30)
expect_tiles_failure(tiles_empty "no input point" "${WORK}/empty.xyz" "${WORK}/tiles_empty_dir" --tile-size 5)
expect_tiles_failure(tiles_no_size "tile-size" "${b9}" "${WORK}/tiles_no_size_dir")
expect_tiles_failure(tiles_no_parent "no directory" "${b9}" "${WORK}/missing/tiles_no_parent_dir" --tile-size 50)
file(WRITE "${WORK}/not_a_directory" "precious")
expect_cli_failure(tiles_file "${WORK}/not_a_directory/tile_0_0.ply" "${PROGRAM}" tiles "${b9}" "${WORK}/not_a_directory" --tile-size 50)
file(READ "${WORK}/not_a_directory" kept)
if(NOT kept STREQUAL "precious" OR NOT last_error MATCHES "not a directory")
  message(FATAL_ERROR "tiles_file: '${last_error}', or the file was overwritten")
endif()
# good input: 2 x 2 tiles of b9_training.ply, the same with 1 and 2 threads, and a union
# without cracks (one component, one boundary loop)
foreach(threads 1 2)
  execute_process(COMMAND "${PROGRAM}" tiles "${b9}" "${WORK}/b9_tiles_${threads}" --tile-size 60 --threads ${threads}
                          --merged "${WORK}/b9_merged_${threads}.off" --json
                  RESULT_VARIABLE rc OUTPUT_VARIABLE json ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "b9 tiles (${threads} threads): exit code ${rc}: ${err}")
  endif()
endforeach()
expect_json_keys("b9 tiles" "${json}" points tiles columns rows seam_s tiles_s merge_s total_s peak_rss_mb per_tile merged_mesh)
string(JSON tiles GET "${json}" tiles)
string(JSON components GET "${json}" merged_mesh components)
string(JSON loops GET "${json}" merged_mesh boundary_loops)
string(JSON first_tile_faces GET "${json}" per_tile 0 faces)
if(NOT tiles EQUAL 4 OR NOT components EQUAL 1 OR NOT loops EQUAL 1 OR first_tile_faces LESS 1000)
  message(FATAL_ERROR "b9 tiles: not 4 tiles welded into one surface with one boundary loop: ${json}")
endif()
foreach(tile 0_0 1_0 0_1 1_1)
  file(SHA256 "${WORK}/b9_tiles_1/tile_${tile}.ply" one)
  file(SHA256 "${WORK}/b9_tiles_2/tile_${tile}.ply" two)
  if(NOT one STREQUAL two)
    message(FATAL_ERROR "b9 tiles: tile ${tile} differs between 1 and 2 threads")
  endif()
endforeach()
file(SHA256 "${WORK}/b9_merged_1.off" one)
file(SHA256 "${WORK}/b9_merged_2.off" two)
if(NOT one STREQUAL two)
  message(FATAL_ERROR "b9 tiles: the union differs between 1 and 2 threads")
endif()
message(STATUS "b9 tiles: ${json}")
# out of core (the input streamed twice into bucket files): the same tiles and union, byte for
# byte, and no bucket file left
execute_process(COMMAND "${PROGRAM}" tiles "${b9}" "${WORK}/b9_tiles_ooc" --tile-size 60 --out-of-core
                        --bucket-dir "${WORK}" --merged "${WORK}/b9_merged_ooc.off" --json
                RESULT_VARIABLE rc OUTPUT_VARIABLE json ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "b9 tiles out of core: exit code ${rc}: ${err}")
endif()
string(JSON out_of_core GET "${json}" out_of_core)
if(NOT out_of_core)
  message(FATAL_ERROR "b9 tiles out of core: the JSON does not say so: ${json}")
endif()
foreach(tile 0_0 1_0 0_1 1_1)
  file(SHA256 "${WORK}/b9_tiles_1/tile_${tile}.ply" one)
  file(SHA256 "${WORK}/b9_tiles_ooc/tile_${tile}.ply" two)
  if(NOT one STREQUAL two)
    message(FATAL_ERROR "b9 tiles out of core: tile ${tile} differs from the tile made in memory")
  endif()
endforeach()
file(SHA256 "${WORK}/b9_merged_1.off" one)
file(SHA256 "${WORK}/b9_merged_ooc.off" two)
file(GLOB buckets "${WORK}/.lex_tile_buckets*")
if(NOT one STREQUAL two OR buckets)
  message(FATAL_ERROR "b9 tiles out of core: the union differs, or bucket files are left: ${buckets}")
endif()
message(STATUS "b9 tiles out of core: the same tiles and union, byte for byte")
expect_tiles_failure(tiles_no_buckets "bucket directory" "${b9}" "${WORK}/tiles_no_buckets_dir" --tile-size 60
                     --out-of-core --bucket-dir "${WORK}/missing_buckets" --merged "${WORK}/tiles_no_buckets_merged.off")
expect_tiles_failure(tiles_buckets_alone "out-of-core" "${b9}" "${WORK}/tiles_buckets_alone_dir" --tile-size 60 --bucket-dir "${WORK}")

# ----- lex_optimal_triangulation_2: bad input gives one line and exit code 1 -----
if(TRIANGULATION_PROGRAM)
  function(expect_triangulation_failure name content)
    file(WRITE "${WORK}/${name}.txt" "${content}")
    execute_process(COMMAND "${TRIANGULATION_PROGRAM}" "${WORK}/${name}.txt" RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE out)
    string(STRIP "${err}" err)
    if(rc EQUAL 0 OR NOT out STREQUAL "" OR NOT err MATCHES "^lex_optimal_triangulation_2: error: [^\n]*$")
      message(FATAL_ERROR "${name}: expected a one-line error, got exit code ${rc}, '${err}', '${out}'")
    endif()
    message(STATUS "${name}: ${err}")
  endfunction()
  expect_triangulation_failure(two_points "0 0\n1 1\n")
  expect_triangulation_failure(collinear "0 0\n1 1\n2 2\n3 3\n")
  expect_triangulation_failure(mixed "0 0\n1 0 0.5\n0 1\n")
  expect_triangulation_failure(duplicate "0 0\n1 0\n0 1\n1 0\n")
  expect_triangulation_failure(garbage "0 0\nhello\n0 1\n")
  expect_triangulation_failure(nan "0 0\n1 0\nnan 1\n")
  # a square with its center: four triangles around the center
  file(WRITE "${WORK}/square.txt" "0 0\n2 0\n2 2\n0 2\n1 1.1\n")
  execute_process(COMMAND "${TRIANGULATION_PROGRAM}" "${WORK}/square.txt" RESULT_VARIABLE rc OUTPUT_VARIABLE out)
  if(NOT rc EQUAL 0 OR NOT out STREQUAL "0 1 4\n0 3 4\n1 2 4\n2 3 4\n")
    message(FATAL_ERROR "square: got '${out}'")
  endif()
endif()

# Interrupted by a signal (the SIGTERM of a scheduler, the SIGHUP of a closed terminal; Ctrl-C's
# SIGINT takes the same path) while it works on a million points: the signal ends the run (exit
# status 128 + signal) and no output nor temporary file is left. The signal is sent once the
# temporary file exists (a SIGKILL, which no program can catch, would leave it). A signal
# ignored when the program starts stays ignored (nohup; sh starts a background job with SIGINT
# ignored): the run is complete.
find_program(SH_PROGRAM sh)
find_program(AWK_PROGRAM NAMES awk mawk gawk)
if(NOT SH_PROGRAM OR NOT AWK_PROGRAM)
  message(FATAL_ERROR "the interrupted runs need sh and awk")
endif()
execute_process(COMMAND "${AWK_PROGRAM}" "BEGIN { srand(1); for(i = 0; i < 1000000; ++i) { z = 2 * rand() - 1; t = 6.2831853 * rand(); r = sqrt(1 - z * z); printf \"%.6f %.6f %.6f\\n\", r * cos(t), r * sin(t), z } }"
                OUTPUT_FILE "${WORK}/sphere_million.xyz" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the million points could not be written")
endif()
# sh -c SCRIPT _ PROGRAM INPUT OUTPUT TEMPORARY SIGNAL: prints the exit status of the program
set(interrupt_script [=[
"$1" closed "$2" "$3" --max-memory 100000 >/dev/null 2>&1 &
pid=$!
n=0
while [ ! -e "$4" ] && [ $n -lt 1000 ]; do sleep 0.01; n=$((n + 1)); done
kill -s "$5" $pid
wait $pid
echo $?
]=])
foreach(signal TERM HUP INT)
  file(REMOVE "${WORK}/interrupted.off")
  execute_process(COMMAND "${SH_PROGRAM}" -c "${interrupt_script}" _ "${PROGRAM}" "${WORK}/sphere_million.xyz"
                          "${WORK}/interrupted.off" "${WORK}/.interrupted.partial.off" ${signal}
                  OUTPUT_VARIABLE status OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(signal STREQUAL "INT") # ignored in the background job
    if(NOT status STREQUAL "0" OR NOT EXISTS "${WORK}/interrupted.off")
      message(FATAL_ERROR "SIGINT ignored at the start: exit status ${status}, the run should be complete")
    endif()
    message(STATUS "SIGINT ignored at the start: still ignored, the run complete")
    continue()
  elseif(signal STREQUAL "TERM")
    set(expected 143)
  else()
    set(expected 129)
  endif()
  if(NOT status STREQUAL expected)
    message(FATAL_ERROR "interrupted by SIG${signal}: exit status ${status}, not ${expected} (the signal did not end the run)")
  endif()
  file(GLOB left "${WORK}/interrupted*" "${WORK}/.interrupted*")
  if(left)
    message(FATAL_ERROR "interrupted by SIG${signal}: left ${left}")
  endif()
  message(STATUS "interrupted by SIG${signal}: exit status ${status}, nothing left")
endforeach()
file(REMOVE "${WORK}/sphere_million.xyz")

# A cloud that needs more memory than the run may use is refused before the triangulation
# (kitten.xyz: 5,210 points, about 4 MB in closed): with --max-memory below its
# need, by every subcommand that triangulates it whole; with more, it runs.
expect_failure_because(memory_closed "points need about [0-9]+ MB, more than the 1 MB of --max-memory"
                       closed "${DATA}/points_3/kitten.xyz" --max-memory 1)
expect_failure_because(memory_open "points need about [0-9]+ MB, more than the 1 MB of --max-memory"
                       open "${DATA}/points_3/kitten.xyz" --auto-boundary --max-memory 1)
expect_failure_because(memory_features "points need about [0-9]+ MB, more than the 1 MB of --max-memory"
                       features "${DATA}/points_3/kitten.xyz" --max-memory 1)
expect_failure(memory_zero closed "${DATA}/points_3/kitten.xyz" --max-memory 0)
execute_process(COMMAND "${PROGRAM}" closed "${DATA}/points_3/kitten.xyz" "${WORK}/memory_enough.off" --max-memory 64
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS "${WORK}/memory_enough.off")
  message(FATAL_ERROR "memory_enough: exit code ${rc}: ${err}")
endif()
