// Helpers of the headless demo tests. The drivers (run_demo_test.cmake, and
// run_partition_demo_test.cmake, which adds partition_common.js after this file) give the demo,
// in this order: a "javascript:" argument that sets DATA (the folder of the input data) and OUT
// (the output folder), this file, and the test script. (Not include(): the declarations of a
// file that a script includes are local to the call.) A test builds a `result` object and calls
// finish(result): one "RESULT <json>" line for the driver, then the demo quits. Anything
// thrown is reported as {"failure": ...} rather than left to block the demo. statistics() and
// snapshot() are those of the Lex_optimal_chains plugin. Scripts ask the plugins or the scene by
// item index (itemVisible(i), scene.setItemVisible(i, b)) and never hold scene.item(i): CGAL
// Lab's script engine (QJSEngine) would take that item and delete it when the demo quits.

// loads a file with the named IO plugin and returns the index of the new item
function load(path, loader) {
    var before = scene.numberOfEntries
    main_window.open(path, loader)
    if (scene.numberOfEntries != before + 1)
        throw "cannot load " + path + " with " + loader
    return scene.numberOfEntries - 1
}

// the statistics of a surface mesh item, as an object
function statistics(item) {
    var json = lex_optimal_chains_plugin.meshStatistics(item)
    if (json == "")
        throw "item " + item + " is not a surface mesh"
    return JSON.parse(json)
}

function snapshot(name) {
    if (!lex_optimal_chains_plugin.saveSnapshot(OUT + "/" + name))
        throw lex_optimal_chains_plugin.lastError()
}

function finish(result) {
    print("RESULT " + JSON.stringify(result))
    main_window.quit()
}

function run_test(test) {
    var result
    try {
        result = test()
    } catch (e) {
        result = { failure: String(e) }
    }
    finish(result)
}
