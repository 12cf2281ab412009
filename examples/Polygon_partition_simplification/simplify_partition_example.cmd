data/footprints_25.txt
