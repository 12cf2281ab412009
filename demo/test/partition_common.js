// Helpers of the headless tests of the Polygon_partition_simplification plugin, given to the
// demo after common.js (load(), run_test(), finish()) and before the test script.

var pps = polygon_partition_simplification_plugin

// the index an item-making slot returned, or its reason thrown
function checked(item) {
    if (item < 0)
        throw pps.lastError()
    return item
}

// the statistics of the last kinetic partition or simplification, as an object
function last_statistics() {
    return JSON.parse(pps.lastStatistics())
}

// the statistics of an item of a partition made by the plugin, as an object
function partition_statistics(item) {
    var json = pps.partitionStatistics(item)
    if (json == "")
        throw "item " + item + " is not an item of a partition"
    return JSON.parse(json)
}

function partition_snapshot(name) {
    if (!pps.saveSnapshot(OUT + "/" + name))
        throw pps.lastError()
}

// runs f (a plugin call returning an item index) and records what it left: the item, the
// reason, the number of items before and after
function attempt(f) {
    var before = scene.numberOfEntries
    var item = f()
    return { item: item, error: pps.lastError(), entries_before: before, entries_after: scene.numberOfEntries }
}
