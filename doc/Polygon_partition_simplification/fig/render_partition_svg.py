#!/usr/bin/python3
"""Renders the SVG written by `simplify_partition --svg` (the partition before, in black, and
after simplification, in dark blue, side by side) to a PNG for the manual: the two partitions
on top, a zoom on a window (x0 y0 x1 y1, input units) below them.
   simplify_partition data/footprints_25.txt out.geojson --svg x.svg
   /usr/bin/python3 render_partition_svg.py x.svg out.png "title before" "title after" x0 y0 x1 y1
Needs Debian's python3-matplotlib and python3-pil."""
import re
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import LineCollection
from matplotlib.patches import Rectangle
from PIL import Image

svg, out, title_before, title_after = sys.argv[1:5]
zx0, zy0, zx1, zy1 = map(float, sys.argv[5:9])
text = open(svg).read()
# simplify_partition: viewBox = (xmin - gap, -ymax - gap, 2 w + 3 gap, h + 2 gap), gap = 0.05 w,
# y flipped, the partition after shifted right by w + gap
vb = [float(v) for v in re.search(r"viewBox='([^']+)'", text).group(1).split()]
w = vb[2] / 2.15
gap = 0.05 * w
segments = {"black": [], "darkblue": []}
for m in re.finditer(r"<line x1='([^']+)' y1='([^']+)' x2='([^']+)' y2='([^']+)' stroke='([^']+)'", text):
    x1, y1, x2, y2 = map(float, m.group(1, 2, 3, 4))
    shift = w + gap if m.group(5) == "darkblue" else 0.
    segments[m.group(5)].append([(x1 - shift, -y1), (x2 - shift, -y2)])
xmin, ymax = vb[0] + gap, -vb[1] - gap
ymin = ymax - (vb[3] - 2 * gap)

fig, axes = plt.subplots(2, 2, figsize=(12, 12.3), dpi=100)
for column, (color, title) in enumerate([("black", title_before), ("darkblue", title_after)]):
    for row in range(2):
        ax = axes[row][column]
        ax.add_collection(LineCollection(segments[color], colors=color, linewidths=0.6 if row == 0 else 1.2))
        if row == 0:
            ax.set_xlim(xmin - 1, xmin + w + 1)
            ax.set_ylim(ymin - 1, ymax + 1)
            ax.add_patch(Rectangle((zx0, zy0), zx1 - zx0, zy1 - zy0, fill=False, ec="red", lw=1.2))
            ax.set_title(title, color=color, fontsize=12)
            for spine in ax.spines.values(): spine.set_visible(False)
        else:
            ax.set_xlim(zx0, zx1)
            ax.set_ylim(zy0, zy1)
            for spine in ax.spines.values(): spine.set_edgecolor("red")
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_yticks([])
fig.subplots_adjust(left=0.01, right=0.99, bottom=0.01, top=0.96, wspace=0.03, hspace=0.03)
fig.savefig(out, dpi=100)
Image.open(out).convert("RGB").quantize(colors=32).save(out, optimize=True)
