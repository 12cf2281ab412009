#!/usr/bin/python3
"""Renders the mesh of `lex_reconstruct features` (a binary PLY whose faces have the int
property `element`), one colour per element of the critical basis, with flat shading (for the
manual's figure).
   /usr/bin/python3 render_elements.py mesh.ply out.png [azimuth elevation]
Needs Debian's python3-matplotlib."""
import struct
import sys
import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

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

colours = [(0.55, 0.70, 0.90), (0.95, 0.70, 0.45), (0.60, 0.85, 0.55), (0.90, 0.60, 0.75),
           (0.75, 0.70, 0.95), (0.95, 0.90, 0.50), (0.55, 0.85, 0.85), (0.85, 0.65, 0.55),
           (0.70, 0.90, 0.70), (0.95, 0.55, 0.55), (0.60, 0.60, 0.85), (0.85, 0.85, 0.85)]
v, faces, element = read_element_ply(sys.argv[1])
azim, elev = (float(sys.argv[3]), float(sys.argv[4])) if len(sys.argv) > 4 else (-60.0, 35.0)
a, e = np.radians(azim), np.radians(elev)
view = np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])
tri = v[faces]
n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
n /= np.linalg.norm(n, axis=1)[:, None] + 1e-300
shade = 0.3 + 0.7 * np.abs(n @ view)
base = np.array([colours[k % len(colours)] for k in element])
fig = plt.figure(figsize=(6, 6), dpi=120)
ax = fig.add_subplot(111, projection="3d")
ax.add_collection3d(Poly3DCollection(tri, facecolors=base * shade[:, None], linewidths=0))
lo, hi = v.min(0), v.max(0)
c, r = (lo + hi) / 2, (hi - lo).max() / 2
ax.set_xlim(c[0] - r, c[0] + r); ax.set_ylim(c[1] - r, c[1] + r); ax.set_zlim(c[2] - r, c[2] + r)
ax.view_init(elev=elev, azim=azim)
ax.set_axis_off()
plt.tight_layout()
plt.savefig(sys.argv[2], bbox_inches="tight")
