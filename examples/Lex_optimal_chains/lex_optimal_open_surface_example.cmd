${URBAN_CGAL_DATA_DIR}/points_3/b9_training.ply b9_open.off
