${URBAN_CGAL_DATA_DIR}/points_3/building.ply
