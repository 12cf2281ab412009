#!/usr/bin/python3
"""Renders an OFF triangle mesh to a PNG with flat shading (for the manual's figures).
   /usr/bin/python3 render_mesh.py mesh.off out.png [azimuth elevation]
Needs Debian's python3-matplotlib."""
import sys
import numpy as np
from mpl_toolkits.mplot3d.art3d import Poly3DCollection
from flat_shading import new_axes, save_view, unit_normals, view_angles, view_direction

def read_off(path):
    with open(path) as f:
        tokens = [t for line in f for t in line.split("#")[0].split()]
    assert tokens[0] == "OFF"
    nv, nf = int(tokens[1]), int(tokens[2])
    v = np.array(tokens[4:4 + 3 * nv], dtype=float).reshape(nv, 3)
    faces, i = [], 4 + 3 * nv
    for _ in range(nf):
        k = int(tokens[i]); faces.append([int(x) for x in tokens[i + 1:i + 1 + k]]); i += 1 + k
    return v, np.array(faces)

v, f = read_off(sys.argv[1])
azim, elev = view_angles(sys.argv, 20.0)
tri = v[f]
shade = 0.25 + 0.75 * np.clip(unit_normals(tri) @ view_direction(azim, elev), 0, 1)
ax = new_axes(5)
ax.add_collection3d(Poly3DCollection(tri, facecolors=np.outer(shade, [0.55, 0.7, 0.9]), edgecolors=(0, 0, 0, 0.15), linewidths=0.1))
save_view(ax, v.min(0), v.max(0), azim, elev, sys.argv[2])
