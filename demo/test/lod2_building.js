// "LOD2 building model" on CGAL's building.ply (planes from its segment_index property), as
// `lod2_reconstruct building.ply out.off --planes segment_index --json`: the driver compares the
// numbers of planes, segments, cells, buildings and faces, and closedness.
run_test(function () {
    var points = load(DATA + "/building.ply", "ply_plugin")
    var model = checked(pps.lod2Model(points))
    var lod2 = last_statistics()
    partition_snapshot("building_lod2.png")
    // a polylines item is not a point set: no item, the reason
    var segments = load(SEGMENTS, "segments_2_io_plugin")
    var refused = attempt(function () { return pps.lod2Model(segments) })
    return { lod2: lod2, model_item: model, mesh: statistics(model), refused: refused,
             actions: [actionLod2BuildingModel.text] }
})
