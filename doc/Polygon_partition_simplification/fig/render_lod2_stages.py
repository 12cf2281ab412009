#!/usr/bin/python3
"""Draws the stages of the LOD2 pipeline written by `lod2_stages_example building.ply DIR` as one
PNG for the manual: the points by plane, the 2D segments, the kinetic partition, its
simplification, the roofs of the model by plane (top views, turned by 90 degrees when the scene
is taller than wide), and the model in 3D.
   lod2_stages_example .../points_3/building.ply DIR
   /usr/bin/python3 render_lod2_stages.py DIR lod2_stages.png
Needs Debian's python3-matplotlib."""
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import LineCollection, PolyCollection
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

directory, out = sys.argv[1:3]


def rows(name):
    with open(f"{directory}/{name}") as f:
        return [list(map(float, line.split())) for line in f if line.strip()]


points = rows("points.txt")
segments = rows("segments.txt")
partition = rows("partition.txt")
simplified = rows("simplified.txt")
faces = []  # (type, plane, [(x, y, z), ...])
for r in rows("model.txt"):
    faces.append((int(r[0]), int(r[1]), [tuple(r[i:i + 3]) for i in range(2, len(r), 3)]))
# the top views are turned by 90 degrees when the scene is taller than wide: (x, y) -> (y, -x)
turn = max(p[1] for p in points) - min(p[1] for p in points) > max(p[0] for p in points) - min(p[0] for p in points)


def view(x, y):
    return (y, -x) if turn else (x, y)


for rows_of_segments in (segments, partition, simplified):
    for s in rows_of_segments:
        s[0:2] = view(s[0], s[1])
        s[2:4] = view(s[2], s[3])

colors = plt.get_cmap("tab20").colors


def plane_color(p):
    return (0.8, 0.8, 0.8) if p < 0 else colors[p % len(colors)]


xs = [view(p[0], p[1])[0] for p in points]
ys = [view(p[0], p[1])[1] for p in points]
x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
fig = plt.figure(figsize=(14, 9))


def top_view(index, title):
    ax = fig.add_subplot(3, 2, index)
    ax.set_title(title, fontsize=11)
    ax.set_aspect("equal")
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_xticks([])
    ax.set_yticks([])
    return ax


ax = top_view(1, f"1. {len(points):,} points by plane (grey: on none)")
ax.scatter(xs, ys, s=0.6, c=[plane_color(int(p[3])) for p in points], linewidths=0)
ax = top_view(2, f"2. {len(segments)} segments (red: facades)")
ax.scatter(xs, ys, s=0.1, c="0.85", linewidths=0)
ax.add_collection(LineCollection([[(s[0], s[1]), (s[2], s[3])] for s in segments],
                                 colors=["red" if s[4] else "navy" for s in segments], linewidths=1.2))
for index, edges, title in ((3, partition, "3. kinetic partition"), (4, simplified, "4. simplified partition")):
    ax = top_view(index, f"{title} ({len(edges)} edges)")
    ax.add_collection(LineCollection([[(e[0], e[1]), (e[2], e[3])] for e in edges], colors="black", linewidths=0.8))
ax = top_view(5, "5. roofs of the model by plane (graph cut)")
roofs = [f for f in faces if f[0] == 0]
ax.add_collection(PolyCollection([[view(x, y) for x, y, _ in f[2]] for f in roofs],
                                 facecolors=[plane_color(f[1]) for f in roofs], edgecolors="black", linewidths=0.5))
ax = fig.add_subplot(3, 2, 6, projection="3d")
ax.set_title(f"6. the model: {len(faces)} faces, closed", fontsize=11)
shade = {0: None, 1: (0.75, 0.75, 0.7), 2: (0.5, 0.5, 0.5)}
ax.add_collection3d(Poly3DCollection([f[2] for f in faces],
                                     facecolors=[plane_color(f[1]) if f[0] == 0 else shade[f[0]] for f in faces],
                                     edgecolors="black", linewidths=0.4))
xs3 = [v[0] for f in faces for v in f[2]]
ys3 = [v[1] for f in faces for v in f[2]]
zs3 = [v[2] for f in faces for v in f[2]]
ax.set_xlim(min(xs3), max(xs3))
ax.set_ylim(min(ys3), max(ys3))
ax.set_zlim(min(zs3), max(zs3))
ax.set_box_aspect((max(xs3) - min(xs3), max(ys3) - min(ys3), max(zs3) - min(zs3)))
ax.view_init(elev=30, azim=-30 if turn else -60)
ax.set_axis_off()
fig.tight_layout()
fig.savefig(out, dpi=80)
