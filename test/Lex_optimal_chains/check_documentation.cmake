# Builds the reference and user manuals out of the source tree; fails on any Doxygen warning.
# Arguments: DOXYGEN, DOC_DIR (the doc/ folder), OUT (output folder).
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
file(READ "${DOC_DIR}/Doxyfile" config)
file(WRITE "${OUT}/Doxyfile" "${config}\nOUTPUT_DIRECTORY = ${OUT}\nWARN_LOGFILE = ${OUT}/warnings.txt\n")
execute_process(COMMAND "${DOXYGEN}" "${OUT}/Doxyfile" WORKING_DIRECTORY "${DOC_DIR}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(READ "${OUT}/warnings.txt" warnings)
if(NOT rc EQUAL 0 OR NOT warnings STREQUAL "" OR NOT err STREQUAL "")
  message(FATAL_ERROR "Doxygen failed or warned (exit code ${rc}):\n${err}\n${warnings}")
endif()
if(NOT EXISTS "${OUT}/html/Chapter_Lex_optimal_chains.html")
  message(FATAL_ERROR "the user manual page was not generated")
endif()
message(STATUS "documentation built without warnings in ${OUT}/html")
