#!/usr/bin/python3
"""Renders the tiles of `lex_reconstruct tiles ... --ascii` (ASCII PLY meshes tile_C_R.ply),
each in its own colour, with flat shading (for the manual's figure).
   /usr/bin/python3 render_tiles.py TILE_DIR out.png [azimuth elevation]
Needs Debian's python3-matplotlib."""
import glob
import os
import sys
import numpy as np
from mpl_toolkits.mplot3d.art3d import Poly3DCollection
from flat_shading import PALETTE, new_axes, save_view, unit_normals, view_angles, view_direction

def read_ascii_ply(path):
    with open(path) as f:
        counts, line = {}, f.readline()
        while not line.startswith("end_header"):
            words = line.split()
            if words and words[0] == "element":
                counts[words[1]] = int(words[2])
            line = f.readline()
        v = np.array([f.readline().split()[:3] for _ in range(counts["vertex"])], dtype=float)
        faces = [[int(x) for x in f.readline().split()[1:4]] for _ in range(counts["face"])]
    return v, np.array(faces)

azim, elev = view_angles(sys.argv, 35.0)
view = view_direction(azim, elev)
palette = PALETTE[:8] # eight colours, as in the manual's figure of nine tiles
ax = new_axes(6)
lo, hi = np.full(3, np.inf), np.full(3, -np.inf)
for k, path in enumerate(sorted(glob.glob(os.path.join(sys.argv[1], "tile_*.ply")))):
    v, f = read_ascii_ply(path)
    tri = v[f]
    shade = 0.3 + 0.7 * np.abs(unit_normals(tri) @ view)
    ax.add_collection3d(Poly3DCollection(tri, facecolors=np.outer(shade, palette[k % len(palette)]), linewidths=0))
    lo, hi = np.minimum(lo, v.min(0)), np.maximum(hi, v.max(0))
save_view(ax, lo, hi, azim, elev, sys.argv[2])
