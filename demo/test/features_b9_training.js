// "Feature-guided reconstruction (lexicographic)" on b9_training.ply (aerial LiDAR), with the
// defaults and with the largest element left out, as lex_reconstruct features [--drop-largest 1]:
// the driver compares the mesh statistics and the number of elements (colours); a bad threshold
// gives the library's reason and no item.
run_test(function () {
    var points = load(DATA + "/b9_training.ply", "ply_plugin")
    var item = lex_optimal_chains_plugin.featureReconstruction(points)
    if (item < 0)
        throw lex_optimal_chains_plugin.lastError()
    var dropped = lex_optimal_chains_plugin.featureReconstruction(points, 0.16, 0, 1)
    if (dropped < 0)
        throw lex_optimal_chains_plugin.lastError()
    scene.setItemVisible(dropped, false)
    snapshot("features_b9_training.png")
    var entries = scene.numberOfEntries
    var bad = lex_optimal_chains_plugin.featureReconstruction(points, -1)
    return { mesh: statistics(item), dropped: statistics(dropped),
             bad: { item: bad, error: lex_optimal_chains_plugin.lastError(), entries_before: entries,
                    entries_after: scene.numberOfEntries },
             actions: [actionLexFeatures.text] }
})
