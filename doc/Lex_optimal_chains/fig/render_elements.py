#!/usr/bin/python3
"""Renders the mesh of `lex_reconstruct features` (a binary PLY whose faces have the int
property `element`), one colour per element of the critical basis, with flat shading (for the
manual's figure).
   /usr/bin/python3 render_elements.py mesh.ply out.png [azimuth elevation]
Needs Debian's python3-matplotlib."""
import struct
import sys
import numpy as np
from mpl_toolkits.mplot3d.art3d import Poly3DCollection
from flat_shading import PALETTE, new_axes, save_view, unit_normals, view_angles, view_direction

def read_element_ply(path):
    with open(path, "rb") as f:
        counts, line = {}, f.readline().decode()
        while not line.startswith("end_header"):
            words = line.split()
            if words and words[0] == "element":
                counts[words[1]] = int(words[2])
            line = f.readline().decode()
        v = np.frombuffer(f.read(24 * counts["vertex"]), dtype="<f8").reshape(-1, 3)
        records = np.frombuffer(f.read(17 * counts["face"]), dtype=np.dtype([("n", "u1"), ("v", "<i4", 3), ("e", "<i4")]))
    return v, records["v"], records["e"]

v, faces, element = read_element_ply(sys.argv[1])
azim, elev = view_angles(sys.argv, 35.0)
tri = v[faces]
shade = 0.3 + 0.7 * np.abs(unit_normals(tri) @ view_direction(azim, elev))
base = np.array([PALETTE[k % len(PALETTE)] for k in element])
ax = new_axes(6)
ax.add_collection3d(Poly3DCollection(tri, facecolors=base * shade[:, None], linewidths=0))
save_view(ax, v.min(0), v.max(0), azim, elev, sys.argv[2])
