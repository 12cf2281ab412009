# A CGAL found outside the compiler's system directories (e.g. CGAL 6.0.1 unpacked by
# scripts/fetch_cgal6.sh next to Debian's CGAL 5.5.1) comes first on the include path, but the
# headers that only the system's CGAL has would still be found behind it, in /usr/include, and
# mix two CGALs in one program. Each of them gets a stub that stops the compilation with the
# reason; URBAN_SYSTEM_CGAL_STUBS is the folder of the stubs (empty when there is nothing to stop).
include_guard(GLOBAL)

function(urban_write_system_CGAL_stubs)
  set(URBAN_SYSTEM_CGAL_STUBS "" PARENT_SCOPE)
  set(cgal_include "")
  foreach(dir IN LISTS CGAL_INCLUDE_DIRS)
    if(NOT cgal_include AND EXISTS "${dir}/CGAL/version.h")
      get_filename_component(cgal_include "${dir}" REALPATH)
    endif()
  endforeach()
  set(system_include "")
  foreach(dir IN LISTS CMAKE_CXX_IMPLICIT_INCLUDE_DIRECTORIES)
    get_filename_component(dir "${dir}" REALPATH)
    if(NOT system_include AND EXISTS "${dir}/CGAL/version.h" AND NOT dir STREQUAL cgal_include)
      set(system_include "${dir}")
    endif()
  endforeach()
  if(NOT cgal_include OR NOT system_include)
    return()
  endif()
  set(stubs "${CMAKE_BINARY_DIR}/system-CGAL-stubs")
  file(REMOVE_RECURSE "${stubs}")
  file(GLOB_RECURSE headers RELATIVE "${system_include}" "${system_include}/CGAL/*")
  set(count 0)
  foreach(header IN LISTS headers)
    if(NOT EXISTS "${cgal_include}/${header}")
      file(WRITE "${stubs}/${header}"
           "#error \"<${header}> is not part of CGAL ${CGAL_VERSION} (${cgal_include}); the one in \
${system_include} belongs to another CGAL and must not be mixed in\"\n")
      math(EXPR count "${count} + 1")
    endif()
  endforeach()
  message(STATUS "${count} headers of the CGAL in ${system_include} are stopped by stubs in ${stubs}")
  set(URBAN_SYSTEM_CGAL_STUBS "${stubs}" PARENT_SCOPE)
endfunction()

urban_write_system_CGAL_stubs()
