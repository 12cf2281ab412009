"""What the figure scripts of this folder share: the direction of the view, the unit normals of
triangles, a palette, and the last steps of a figure (equal axes around the mesh, the view,
no axes, the PNG). Needs Debian's python3-matplotlib."""
import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

# one colour per element or tile, in this order
PALETTE = [(0.55, 0.70, 0.90), (0.95, 0.70, 0.45), (0.60, 0.85, 0.55), (0.90, 0.60, 0.75),
           (0.75, 0.70, 0.95), (0.95, 0.90, 0.50), (0.55, 0.85, 0.85), (0.85, 0.65, 0.55),
           (0.70, 0.90, 0.70), (0.95, 0.55, 0.55), (0.60, 0.60, 0.85), (0.85, 0.85, 0.85)]

def view_angles(argv, elevation):
    """(azimuth, elevation) in degrees: argv[3] and argv[4] if given, else -60 and `elevation`."""
    return (float(argv[3]), float(argv[4])) if len(argv) > 4 else (-60.0, elevation)

def view_direction(azim, elev):
    """The unit vector towards the viewer of matplotlib's view_init(elev, azim)."""
    a, e = np.radians(azim), np.radians(elev)
    return np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])

def unit_normals(tri):
    """The unit normals of the triangles `tri` (an array of shape (n, 3, 3))."""
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    return n / (np.linalg.norm(n, axis=1)[:, None] + 1e-300)

def new_axes(size):
    """A square figure of `size` inches and its 3D axes."""
    fig = plt.figure(figsize=(size, size), dpi=120)
    return fig.add_subplot(111, projection="3d")

def save_view(ax, lo, hi, azim, elev, path):
    """Equal axes around the box [lo, hi], the view, no axes drawn; writes the PNG `path`."""
    c, r = (lo + hi) / 2, (hi - lo).max() / 2
    ax.set_xlim(c[0] - r, c[0] + r); ax.set_ylim(c[1] - r, c[1] + r); ax.set_zlim(c[2] - r, c[2] + r)
    ax.view_init(elev=elev, azim=azim)
    ax.set_axis_off()
    plt.tight_layout()
    plt.savefig(path, bbox_inches="tight")
