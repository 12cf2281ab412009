# Fuzz harnesses: programs that define libFuzzer's LLVMFuzzerTestOneInput() and abort on a
# finding. Configured with URBAN_FUZZING=ON (Clang; scripts/fuzz.sh does it, in build-fuzz/),
# each is a libFuzzer program with AddressSanitizer and UndefinedBehaviorSanitizer, built on
# demand (not by `all`). Otherwise each is built with a main() that replays its corpus folder
# (the seeds and every input that once failed), and ctest runs it: the corpus is a regression
# test with any compiler.
include_guard(GLOBAL)
option(URBAN_FUZZING "Build the fuzz harnesses as libFuzzer programs with sanitizers (Clang)" OFF)
if(URBAN_FUZZING AND NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  message(FATAL_ERROR "URBAN_FUZZING needs Clang's libFuzzer: configure with -DCMAKE_CXX_COMPILER=clang++")
endif()

# urban_fuzz_harness(NAME CORPUS LABEL [NO_VPTR]): the harness NAME.cpp of the current folder,
# its corpus folder CORPUS, the ctest label LABEL. NO_VPTR: UndefinedBehaviorSanitizer without
# its vptr check, for harnesses that use CGAL's Arrangement_2: its handles static_cast the
# records of its DCEL (Arr_face, ...) to the arrangement's Face, Halfedge and Vertex, classes
# derived from them that add no data, which the vptr check reports as a downcast to a type the
# object is not of.
function(urban_fuzz_harness name corpus label)
  cmake_parse_arguments(FUZZ "NO_VPTR" "" "" ${ARGN})
  if(URBAN_FUZZING)
    set(sanitizers -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all)
    if(FUZZ_NO_VPTR)
      list(APPEND sanitizers -fno-sanitize=vptr)
    endif()
    add_executable(${name} EXCLUDE_FROM_ALL ${name}.cpp)
    target_compile_options(${name} PRIVATE ${sanitizers} -O1 -g -UNDEBUG) # -O1: builds fast, runs fast enough
    target_link_options(${name} PRIVATE ${sanitizers})
  else()
    add_executable(${name} ${name}.cpp ${URBAN_PACKAGES_ROOT}/test/fuzz_support/fuzz_replay_main.cpp)
    target_compile_options(${name} PRIVATE -UNDEBUG) # checks stay active in Release builds
    add_test(NAME execution___of__${name}_corpus COMMAND ${name} ${corpus})
    set_tests_properties(execution___of__${name}_corpus PROPERTIES LABELS "${label};fuzz")
  endif()
endfunction()
