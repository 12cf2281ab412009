# AddressSanitizer and UndefinedBehaviorSanitizer for the tests, the examples and the
# command-line programs (URBAN_SANITIZERS=ON; `URBAN_SANITIZE=1 bash scripts/quickstart.sh test`
# builds the CGAL 6.0.1 pass so, with Clang): the folders of the tests and of the examples call
# urban_sanitize_this_directory(). The demo is left alone (Qt and the GL drivers are not ours),
# apart from the command-line programs it builds as references (urban_sanitize_target).
# A report aborts the program (-fno-sanitize-recover=all; LeakSanitizer exits with an error
# code): its test fails. At -O1 an instrumented test takes about five times its time in
# Release; -g1 gives the reports their source lines. NDEBUG stays as in
# Release: the programs check what they check in Release, and the tests turn their checks on
# themselves (-UNDEBUG). Clang compiles an instrumented test of the packages in about 1.2 times
# the time g++ takes at -O3, g++ in about 2.1 times (and twice the memory): the sanitized pass
# of the test command uses Clang.
include_guard(GLOBAL)
option(URBAN_SANITIZERS "Build the tests, examples and programs with AddressSanitizer and UndefinedBehaviorSanitizer (g++ or Clang)" OFF)
if(URBAN_SANITIZERS AND NOT CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  message(FATAL_ERROR "URBAN_SANITIZERS needs g++ or Clang (-fsanitize=address,undefined)")
endif()

set(URBAN_SANITIZER_COMPILE_OPTIONS -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -O1 -g1)
set(URBAN_SANITIZER_LINK_OPTIONS -fsanitize=address,undefined -fno-sanitize-recover=all)

# The sanitizers for the targets of the calling folder and of the folders below it (once).
macro(urban_sanitize_this_directory)
  if(URBAN_SANITIZERS)
    get_directory_property(urban_directory_options COMPILE_OPTIONS)
    if(NOT "-fsanitize=address,undefined" IN_LIST urban_directory_options)
      add_compile_options(${URBAN_SANITIZER_COMPILE_OPTIONS})
      add_link_options(${URBAN_SANITIZER_LINK_OPTIONS})
    endif()
  endif()
endmacro()

# The sanitizers for one target of a folder that is not ours as a whole (the command-line
# programs that the demo's folder builds when the examples are not).
function(urban_sanitize_target target)
  if(URBAN_SANITIZERS)
    target_compile_options(${target} PRIVATE ${URBAN_SANITIZER_COMPILE_OPTIONS})
    target_link_options(${target} PRIVATE ${URBAN_SANITIZER_LINK_OPTIONS})
  endif()
endfunction()

# urban_no_vptr_check(TARGET): UndefinedBehaviorSanitizer without its vptr check for an
# INTERFACE target whose code uses CGAL's Arrangement_2: its handles static_cast the records of
# its DCEL (Arr_face, ...) to the arrangement's Face, Halfedge and Vertex, classes derived from
# them that add no data, which the vptr check reports as a downcast to a type the object is not
# of (in CGAL's code, not in ours).
function(urban_no_vptr_check target)
  if(URBAN_SANITIZERS)
    target_compile_options(${target} INTERFACE -fno-sanitize=vptr)
  endif()
endfunction()
