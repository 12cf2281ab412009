// "Closed surface (lexicographic)" on kitten.xyz with the automatic interior, as
// lex_reconstruct closed kitten.xyz: the driver compares the mesh statistics.
run_test(function () {
    var points = load(DATA + "/kitten.xyz", "xyz_plugin")
    var item = lex_optimal_chains_plugin.closedSurface(points)
    if (item < 0)
        throw lex_optimal_chains_plugin.lastError()
    snapshot("closed_kitten.png")
    // the menu actions exist (a script would block in their dialog: it calls the slots)
    return { mesh: statistics(item), points_visible: scene.item(points).visible,
             actions: [actionLexClosedSurface.text, actionLexOpenSurface.text] }
})
