closed ${URBAN_CGAL_DATA_DIR}/points_3/kitten.xyz kitten_lex.off --json
