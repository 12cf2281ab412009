${URBAN_CGAL_DATA_DIR}/points_3/building.ply building_lod2.off --planes segment_index --json
