# Runs simplify_partition on good and bad input. Arguments: PROGRAM, DATA, WORK.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

include("${CMAKE_CURRENT_LIST_DIR}/../../cmake/Urban_cli_test_functions.cmake")

# expect_failure(name input output [options...]): exit code 1, one line, no output
macro(expect_failure name input out)
  expect_cli_failure(${name} "${out}" "${PROGRAM}" "${input}" "${out}" ${ARGN})
endmacro()

file(WRITE "${WORK}/empty.txt" "")
file(WRITE "${WORK}/comments.txt" "# nothing\n\n")
file(WRITE "${WORK}/nan.txt" "0 0 1 1\n2 2 nan 3\n")
file(WRITE "${WORK}/zero.txt" "0 0 1 1\n2 2 2 2\n")
file(WRITE "${WORK}/duplicate.txt" "0 0 1 1\n1 1 0 0\n")
file(WRITE "${WORK}/short.txt" "0 0 1\n")
file(WRITE "${WORK}/long.txt" "0 0 1 1 5\n")
file(WRITE "${WORK}/good.txt" "0 0 10 0\n10 0 10 10\n10 10 0 10\n0 10 0 0\n3 5 7 5.1\n")
expect_failure(empty "${WORK}/empty.txt" "${WORK}/empty.geojson")
expect_failure(comments "${WORK}/comments.txt" "${WORK}/comments.geojson")
expect_failure(nan "${WORK}/nan.txt" "${WORK}/nan.geojson")
expect_failure(zero_length "${WORK}/zero.txt" "${WORK}/zero.geojson")
expect_failure(three_numbers "${WORK}/short.txt" "${WORK}/short.geojson")
expect_failure(five_numbers "${WORK}/long.txt" "${WORK}/long.geojson")
expect_failure(missing "${WORK}/does_not_exist.txt" "${WORK}/missing.geojson")
expect_failure(format "${WORK}/good.txt" "${WORK}/good.shp")
expect_failure(negative_weight "${WORK}/good.txt" "${WORK}/negative.geojson" --lambda1 -1)
expect_failure(angle "${WORK}/good.txt" "${WORK}/angle.geojson" --alpha-max 100)
expect_failure(zero_epsilon "${WORK}/good.txt" "${WORK}/epsilon.geojson" --epsilon 0)
expect_failure(not_a_number "${WORK}/good.txt" "${WORK}/abc.geojson" --lambda1 abc)
expect_failure(unknown_option "${WORK}/good.txt" "${WORK}/bogus.geojson" --bogus)
expect_failure(no_extension "${WORK}/good.txt" "${WORK}/no_extension")
expect_failure(directory_input "${WORK}" "${WORK}/directory.geojson")
expect_failure(svg_directory "${WORK}/good.txt" "${WORK}/svg.geojson" --svg "${WORK}/no_such_directory/x.svg")

# Good input: GeoJSON and WKT, the JSON line with its keys, the SVG.
execute_process(COMMAND "${PROGRAM}" "${DATA}/footprints_25.txt" "${WORK}/out.geojson" --json --svg "${WORK}/out.svg"
                RESULT_VARIABLE rc OUTPUT_VARIABLE json)
if(NOT rc EQUAL 0 OR NOT EXISTS "${WORK}/out.geojson" OR NOT EXISTS "${WORK}/out.svg")
  message(FATAL_ERROR "simplify_partition failed on good input (${rc})")
endif()
expect_json_keys("simplify_partition" "${json}" segments lines_before lines_after points_before
                 points_after cells_before cells_after orthogonal_pairs_after kinetic_s
                 simplification_s)
string(JSON before GET "${json}" cells_before)
string(JSON after GET "${json}" cells_after)
file(READ "${WORK}/out.geojson" geojson)
string(JSON features LENGTH "${geojson}" features)
if(NOT after LESS before OR NOT features EQUAL after)
  message(FATAL_ERROR "cells ${before} -> ${after}, ${features} GeoJSON features")
endif()
execute_process(COMMAND "${PROGRAM}" "${DATA}/footprints_25.txt" "${WORK}/out.wkt" RESULT_VARIABLE rc OUTPUT_QUIET)
file(READ "${WORK}/out.wkt" wkt)
if(NOT rc EQUAL 0 OR NOT wkt MATCHES "^MULTIPOLYGON")
  message(FATAL_ERROR "no WKT multipolygon written")
endif()
# projected coordinates (millions of meters) keep their decimals in WKT as in GeoJSON: the
# square of good.txt moved to (500000, 4000000), its corners within 1 mm of their place
file(WRITE "${WORK}/projected.txt" "500000 4000000 500010 4000000\n500010 4000000 500010 4000010\n"
     "500010 4000010 500000 4000010\n500000 4000010 500000 4000000\n500003 4000005 500007 4000005.1\n")
execute_process(COMMAND "${PROGRAM}" "${WORK}/projected.txt" "${WORK}/projected.wkt" RESULT_VARIABLE rc OUTPUT_QUIET)
file(READ "${WORK}/projected.wkt" wkt)
if(NOT rc EQUAL 0 OR wkt MATCHES "e\\+0" OR NOT wkt MATCHES "4000000\\.0|4000009\\.99|4000010 ")
  message(FATAL_ERROR "WKT coordinates lost their precision: ${wkt}")
endif()
# segments given twice or overlapping are merged, and counted in the JSON line
file(WRITE "${WORK}/duplicate.txt" "0 0 10 0\n10 0 10 10\n10 10 0 10\n0 10 0 0\n3 5 7 5.1\n0 0 0 10\n10 0 0 0\n10 2 10 8\n")
execute_process(COMMAND "${PROGRAM}" "${WORK}/duplicate.txt" "${WORK}/duplicate.geojson" --json
                RESULT_VARIABLE rc OUTPUT_VARIABLE duplicate_json)
if(NOT rc EQUAL 0 OR NOT EXISTS "${WORK}/duplicate.geojson")
  message(FATAL_ERROR "simplify_partition refused segments given twice (${rc})")
endif()
string(JSON equal GET "${duplicate_json}" equal_segments)
string(JSON overlapping GET "${duplicate_json}" overlapping_segments)
if(NOT equal EQUAL 2 OR NOT overlapping EQUAL 1)
  message(FATAL_ERROR "merged segments: ${equal} equal (2 expected), ${overlapping} overlapping (1 expected)")
endif()
message(STATUS "simplify_partition: ${json}")
