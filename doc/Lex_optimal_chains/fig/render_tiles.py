#!/usr/bin/python3
"""Renders the tiles of `lex_reconstruct tiles ... --ascii` (ASCII PLY meshes tile_C_R.ply),
each in its own colour, with flat shading (for the manual's figure).
   /usr/bin/python3 render_tiles.py TILE_DIR out.png [azimuth elevation]
Needs Debian's python3-matplotlib."""
import glob
import os
import sys
import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

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

colours = [(0.55, 0.70, 0.90), (0.95, 0.70, 0.45), (0.60, 0.85, 0.55), (0.90, 0.60, 0.75),
           (0.75, 0.70, 0.95), (0.95, 0.90, 0.50), (0.55, 0.85, 0.85), (0.85, 0.65, 0.55)]
azim, elev = (float(sys.argv[3]), float(sys.argv[4])) if len(sys.argv) > 4 else (-60.0, 35.0)
a, e = np.radians(azim), np.radians(elev)
view = np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])
fig = plt.figure(figsize=(6, 6), dpi=120)
ax = fig.add_subplot(111, projection="3d")
lo, hi = np.full(3, np.inf), np.full(3, -np.inf)
for k, path in enumerate(sorted(glob.glob(os.path.join(sys.argv[1], "tile_*.ply")))):
    v, f = read_ascii_ply(path)
    tri = v[f]
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    n /= np.linalg.norm(n, axis=1)[:, None] + 1e-300
    shade = 0.3 + 0.7 * np.abs(n @ view)
    ax.add_collection3d(Poly3DCollection(tri, facecolors=np.outer(shade, colours[k % len(colours)]), linewidths=0))
    lo, hi = np.minimum(lo, v.min(0)), np.maximum(hi, v.max(0))
c, r = (lo + hi) / 2, (hi - lo).max() / 2
ax.set_xlim(c[0] - r, c[0] + r); ax.set_ylim(c[1] - r, c[1] + r); ax.set_zlim(c[2] - r, c[2] + r)
ax.view_init(elev=elev, azim=azim)
ax.set_axis_off()
plt.tight_layout()
plt.savefig(sys.argv[2], bbox_inches="tight")
