// footprints_25.txt loaded with the plugin's IO part, "Kinetic partition", then "Simplify
// partition" with the defaults, as `simplify_partition footprints_25.txt ... --json`: the
// driver compares the numbers of segments, lines, points and cells.
run_test(function () {
    var segments = load(DATA + "/footprints_25.txt", "segments_2_io_plugin")
    var kinetic = checked(pps.kineticPartition(segments))
    var kinetic_statistics = last_statistics()
    partition_snapshot("footprints_25_kinetic.png")
    var simplified = checked(pps.simplifyPartition(kinetic))
    var simplification = last_statistics()
    partition_snapshot("footprints_25_simplified.png")
    // the menu actions exist (a script would block in their dialog: it calls the slots)
    return { kinetic: kinetic_statistics,
             kinetic_edges: partition_statistics(kinetic),
             kinetic_cells: partition_statistics(kinetic_statistics.cells_item),
             simplification: simplification,
             edges: partition_statistics(simplified),
             cells: partition_statistics(simplification.cells_item),
             segments_visible: pps.itemVisible(segments),
             kinetic_visible: pps.itemVisible(kinetic),
             simplified_visible: pps.itemVisible(simplified),
             actions: [actionKineticPartition.text, actionSimplifyPartition.text] }
})
