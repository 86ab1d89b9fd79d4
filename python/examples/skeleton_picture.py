"""The Python example of docs/python.md: the skeleton of libcgal-demo's elephant, drawn with matplotlib.

usage: python3 skeleton_picture.py [POINTS_FILE] [PICTURE.png]
(defaults: the elephant from Debian's libcgal-demo, elephant_skeleton_python.png here)
"""
import sys
import tarfile
import tempfile

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy

import pcskeleton


def read_elephant():
    with tempfile.TemporaryDirectory() as folder, tarfile.open("/usr/share/doc/libcgal-dev/data.tar.gz") as archive:
        archive.extract("data/meshes/elephant.off", folder)
        return pcskeleton.read_points(folder + "/data/meshes/elephant.off")


def side_view(cloud):
    """A projection onto the cloud's two longest principal axes: a flat side view."""
    centre = cloud.mean(axis=0)
    axes = numpy.linalg.svd(cloud - centre, full_matrices=False)[2][:2].T
    return lambda xyz: (xyz - centre) @ axes


picture = sys.argv[2] if len(sys.argv) > 2 else "elephant_skeleton_python.png"

points = pcskeleton.read_points(sys.argv[1]) if len(sys.argv) > 1 and sys.argv[1] else read_elephant()
skeleton = pcskeleton.skeletonize(points)
print(skeleton.report["text"])
view = side_view(points)
plt.scatter(*view(points).T, s=1, c=skeleton.correspondence, cmap="tab20", alpha=0.4)
plt.plot(*view(skeleton.nodes)[skeleton.edges].transpose(2, 1, 0), color="black", linewidth=2)

plt.axis("equal")
plt.axis("off")
plt.savefig(picture, dpi=90, bbox_inches="tight")
print("wrote", picture)
