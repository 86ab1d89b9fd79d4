"""The pictures of the README's branches: a scan seen from the side (its height along z),
each point coloured by its skeleton branch, with the table printed.

usage: python3 branches_picture.py [POINTS_FILE] [PICTURE.png]
(defaults: tests/data/scans/corn_v12108.ply, corn_branches.png here; the README's tree is
the authors' tree_small.off, written to tree_branches.png)
"""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

import pcskeleton

here = os.path.dirname(os.path.abspath(__file__))
source = sys.argv[1] if len(sys.argv) > 1 and sys.argv[1] else os.path.join(here, "..", "..", "tests", "data", "scans",
                                                             "corn_v12108.ply")
picture = sys.argv[2] if len(sys.argv) > 2 else "corn_branches.png"

points = pcskeleton.read_points(source)
skeleton = pcskeleton.skeletonize(points)
branches = skeleton.branches
print(branches)
for i in range(len(branches)):
    print(f"branch {i}: order {branches.order[i]}, length {branches.length[i]:.4g}, "
          f"mean radius {branches.mean_radius[i]:.3g}, {branches.points[i]} points")

branch, position = skeleton.point_branches
x, z = 0, 2  # seen from the side: the plant's height is z
plt.figure(figsize=(6, 6))
plt.scatter(points[:, x], points[:, z], s=1, c=branch, cmap="tab20", alpha=0.5)
for a, b in skeleton.edges:
    plt.plot(skeleton.nodes[[a, b], x], skeleton.nodes[[a, b], z], color="black", linewidth=1.5)
plt.title(f"{len(branches)} branches, coloured; orders 1 to {branches.order.max()}")
plt.axis("equal")
plt.axis("off")
plt.savefig(picture, dpi=90, bbox_inches="tight")
print("wrote", picture)
