// "Closed surface (lexicographic)" on kitten.xyz with the automatic interior, as
// lex_reconstruct closed kitten.xyz: the driver compares the mesh statistics.
run_test(function () {
    var points = load(DATA + "/kitten.xyz", "xyz_plugin")
    var item = lex_optimal_chains_plugin.closedSurface(points)
    if (item < 0)
        throw lex_optimal_chains_plugin.lastError()
    snapshot("closed_kitten.png")
    // oni.ply: its automatic interior stands out (the default), and the robust mode
    var oni = load(DATA + "/oni.ply", "ply_plugin")
    var oni_item = lex_optimal_chains_plugin.closedSurface(oni)
    var oni_robust = lex_optimal_chains_plugin.closedSurface(oni, -1, 0, true)
    if (oni_item < 0 || oni_robust < 0)
        throw lex_optimal_chains_plugin.lastError()
    // the menu actions exist (a script would block in their dialog: it calls the slots)
    return { mesh: statistics(item), oni: statistics(oni_item), oni_robust: statistics(oni_robust),
             points_visible: lex_optimal_chains_plugin.itemVisible(points),
             actions: [actionLexClosedSurface.text, actionLexOpenSurface.text] }
})
