# The oracle of the data sweep finds what it must (run with cmake -P). Arguments: CHECKER, DATA
# (CGAL's data), WORK. Each mesh below has one known defect, or none.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

# expect(name verdict file options...): the checker's line on `file` starts with `verdict`
function(expect name verdict file)
  execute_process(COMMAND "${CHECKER}" "${file}" ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE line)
  string(STRIP "${line}" line)
  if(NOT line MATCHES "^${verdict}" OR (verdict STREQUAL "ok" AND NOT rc EQUAL 0) OR (NOT verdict STREQUAL "ok" AND NOT rc EQUAL 1))
    message(FATAL_ERROR "${name}: '${line}' (exit code ${rc}), '${verdict}' expected")
  endif()
  message(STATUS "${name}: ${line}")
endfunction()

set(points "0 0 0\n1 0 0\n0 1 0\n0 0 1\n")
# a tetrahedron, outward and inward
file(WRITE "${WORK}/tetrahedron.off" "OFF\n4 4 0\n${points}3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")
file(WRITE "${WORK}/inward.off" "OFF\n4 4 0\n${points}3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n")
# one face flipped: its edges are used twice in the same direction
file(WRITE "${WORK}/flipped.off" "OFF\n4 4 0\n${points}3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 3 2\n")
# two tetrahedra pinched at a vertex
file(WRITE "${WORK}/pinched.off" "OFF\n7 8 0\n${points}0 0 -1\n0 -1 0\n-1 0 0\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n3 0 4 5\n3 0 5 6\n3 0 6 4\n3 4 6 5\n")
# three triangles on one edge
file(WRITE "${WORK}/fin.off" "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n")
# the tetrahedron with its apex given twice (one copy per face around it), and an unused vertex
file(WRITE "${WORK}/split.off" "OFF\n6 4 0\n${points}0 0 1\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 4 2\n3 1 2 5\n")
file(WRITE "${WORK}/unused.off" "OFF\n5 4 0\n${points}5 5 5\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")
# a triangle (a disk), two triangles apart, a degenerate triangle
file(WRITE "${WORK}/triangle.off" "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
file(WRITE "${WORK}/two.off" "OFF\n6 2 0\n0 0 0\n1 0 0\n0 1 0\n5 0 0\n6 0 0\n5 1 0\n3 0 1 2\n3 3 4 5\n")
file(WRITE "${WORK}/degenerate.off" "OFF\n3 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n")
file(WRITE "${WORK}/nan.off" "OFF\n3 1 0\n0 0 0\n1 0 0\nnan 1 0\n3 0 1 2\n")
file(WRITE "${WORK}/empty.off" "OFF\n0 0 0\n")

expect(tetrahedron ok "${WORK}/tetrahedron.off" --closed)
expect(inward "defect: a component does not bound a positive volume" "${WORK}/inward.off" --closed)
expect(flipped "defect: not an oriented 2-manifold" "${WORK}/flipped.off")
expect(pinched "defect: not an oriented 2-manifold" "${WORK}/pinched.off")
expect(fin "defect: not an oriented 2-manifold" "${WORK}/fin.off")
expect(split_unsaid "defect: 1 points carry several vertices \\(0 said\\)" "${WORK}/split.off")
expect(split_said ok "${WORK}/split.off" --split-points 1)
expect(unused "defect: a vertex that no face uses" "${WORK}/unused.off")
expect(triangle_disk ok "${WORK}/triangle.off" --disk)
expect(triangle_closed "defect: not closed" "${WORK}/triangle.off" --closed)
expect(two_disks "defect: not a disk: 2 components" "${WORK}/two.off" --disk)
expect(tetrahedron_disk "defect: not a disk: 1 components, 0 border cycles" "${WORK}/tetrahedron.off" --disk)
expect(degenerate "defect: a degenerate triangle" "${WORK}/degenerate.off")
expect(nan "defect: (a coordinate is not finite|unreadable)" "${WORK}/nan.off")
expect(empty "defect: (no face|unreadable)" "${WORK}/empty.off")
expect(missing "defect: unreadable" "${WORK}/missing.off")
# CGAL's own meshes: a closed cube, an open one, a tetrahedron crossed by a triangle
expect(cube ok "${DATA}/meshes/cube.off" --closed)
expect(open_cube "defect: not closed" "${DATA}/meshes/open_cube.off" --closed)
expect(intersected "defect: faces intersect" "${DATA}/meshes/tetra_intersected_by_triangle.off")
