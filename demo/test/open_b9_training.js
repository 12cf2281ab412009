// "Open surface (lexicographic)" on b9_training.ply (aerial LiDAR) bounded by the automatic
// footprint polygon, over Q then Z2, as lex_reconstruct open --auto-boundary [--coefficients z2]:
// the driver compares the mesh statistics.
run_test(function () {
    var points = load(DATA + "/b9_training.ply", "ply_plugin")
    var item = lex_optimal_chains_plugin.openSurface(points, -1, true)
    if (item < 0)
        throw lex_optimal_chains_plugin.lastError()
    var item_z2 = lex_optimal_chains_plugin.openSurface(points, -1, false)
    if (item_z2 < 0)
        throw lex_optimal_chains_plugin.lastError()
    scene.setItemVisible(item_z2, false)
    snapshot("open_b9_training.png")
    return { mesh: statistics(item), mesh_z2: statistics(item_z2) }
})
