#!/usr/bin/python3
"""Renders an OFF triangle mesh to a PNG with flat shading (for the manual's figures).
   /usr/bin/python3 render_mesh.py mesh.off out.png [azimuth elevation]
Needs Debian's python3-matplotlib."""
import sys
import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

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
azim, elev = (float(sys.argv[3]), float(sys.argv[4])) if len(sys.argv) > 4 else (-60.0, 20.0)
tri = v[f]
n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
n /= np.linalg.norm(n, axis=1)[:, None] + 1e-300
a, e = np.radians(azim), np.radians(elev)
view = np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])
shade = 0.25 + 0.75 * np.clip(n @ view, 0, 1)
fig = plt.figure(figsize=(5, 5), dpi=120)
ax = fig.add_subplot(111, projection="3d")
ax.add_collection3d(Poly3DCollection(tri, facecolors=np.outer(shade, [0.55, 0.7, 0.9]), edgecolors=(0, 0, 0, 0.15), linewidths=0.1))
lo, hi = v.min(0), v.max(0)
c, r = (lo + hi) / 2, (hi - lo).max() / 2
ax.set_xlim(c[0] - r, c[0] + r); ax.set_ylim(c[1] - r, c[1] + r); ax.set_zlim(c[2] - r, c[2] + r)
ax.view_init(elev=elev, azim=azim)
ax.set_axis_off()
plt.tight_layout()
plt.savefig(sys.argv[2], bbox_inches="tight")
