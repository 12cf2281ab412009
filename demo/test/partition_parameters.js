// "Simplify partition" directly on the segments (the kinetic partition is made first, as
// simplify_partition does), with other parameters: the driver runs simplify_partition with
// the same ones. p1: --lambda1 1 --lambda2 0 --epsilon 0.5 --alpha-max 10;
// p2: --lambda1 0.2 --lambda2 20 --alpha-max 15 (automatic epsilon).
run_test(function () {
    var segments = load(DATA + "/footprints_25.txt", "segments_2_io_plugin")
    var result = {}
    var p1 = checked(pps.simplifyPartition(segments, 1, 0, 0.5, 10))
    result.p1 = last_statistics()
    result.p1_edges = partition_statistics(p1)
    var p2 = checked(pps.simplifyPartition(segments, 0.2, 20, 0, 15))
    result.p2 = last_statistics()
    result.p2_cells = partition_statistics(result.p2.cells_item)
    partition_snapshot("footprints_25_p2.png")
    return result
})
