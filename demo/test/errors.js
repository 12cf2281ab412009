// Bad input and cancellation: no item is made, the library's one-line reason is given, no
// dialog blocks the script, the demo does not crash and the scene keeps its items.

// runs f (a plugin call returning an item index) and records what it left
function attempt(f) {
    var before = scene.numberOfEntries
    var item = f()
    return { item: item, error: lex_optimal_chains_plugin.lastError(),
             entries_before: before, entries_after: scene.numberOfEntries }
}

run_test(function () {
    var result = {}
    var empty = load(OUT + "/empty.xyz", "xyz_plugin")
    result.empty = attempt(function () { return lex_optimal_chains_plugin.closedSurface(empty) })

    // a terrain tile has no interior
    var b9 = load(DATA + "/b9_training.ply", "ply_plugin")
    result.no_interior = attempt(function () { return lex_optimal_chains_plugin.closedSurface(b9) })

    var polyline = load(OUT + "/open.polylines.txt", "polylines_io_plugin")
    result.open_polyline = attempt(function () { return lex_optimal_chains_plugin.openSurface(b9, polyline, true) })

    // Cancel pressed half-way, then the same run to the end
    var kitten = load(DATA + "/kitten.xyz", "xyz_plugin")
    lex_optimal_chains_plugin.setCancelAt(0.5)
    result.cancelled = attempt(function () { return lex_optimal_chains_plugin.closedSurface(kitten) })
    lex_optimal_chains_plugin.setCancelAt(-1)
    var item = lex_optimal_chains_plugin.closedSurface(kitten)
    if (item < 0)
        throw lex_optimal_chains_plugin.lastError()
    result.after_cancel = statistics(item)
    return result
})
