// Bad input: no item is made, the library's one-line reason is given (the driver compares it
// with simplify_partition's on the same input), no dialog blocks the script, the demo does not
// crash and the scene keeps its items. The files are written by run_partition_demo_test.cmake.
run_test(function () {
    var result = {}
    result.missing = attempt(function () { return pps.loadSegments(OUT + "/missing.txt") })
    result.bad_line = attempt(function () { return pps.loadSegments(OUT + "/bad_line.txt") })

    var empty = checked(pps.loadSegments(OUT + "/empty.txt"))
    result.empty = attempt(function () { return pps.kineticPartition(empty) })
    var zero = checked(pps.loadSegments(OUT + "/zero_length.txt"))
    result.zero_length = attempt(function () { return pps.kineticPartition(zero) })

    var segments = checked(pps.loadSegments(DATA + "/footprints_25.txt"))
    var kinetic = checked(pps.kineticPartition(segments))
    result.negative_lambda1 = attempt(function () { return pps.simplifyPartition(kinetic, -1, 5, 0, 5) })
    result.large_angle = attempt(function () { return pps.simplifyPartition(kinetic, 0.5, 5, 0, 120) })
    result.negative_epsilon = attempt(function () { return pps.simplifyPartition(kinetic, 0.5, 5, -1, 5) })
    // not a polylines item: the cells of the partition; no item at all
    result.not_polylines = attempt(function () { return pps.kineticPartition(last_statistics().cells_item) })
    result.no_item = attempt(function () { return pps.simplifyPartition(1000) })

    // the plugin still works, also on the cells of a partition whose edges item was erased:
    // the simplification after the errors above is the one of the CLI
    var cells = last_statistics().cells_item
    scene.erase(kinetic)
    result.after_errors = partition_statistics(checked(pps.simplifyPartition(cells)))
    return result
})
