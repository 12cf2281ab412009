data/tetrahedron.off --closed
