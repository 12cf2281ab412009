data/footprints_25.txt footprints_25_simplified.geojson --json
