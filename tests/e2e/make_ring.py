#!/usr/bin/python3
"""Writes ring.ply: a skeleton of 12 nodes on the unit circle in the xy plane (node i at
30 i degrees, radius in quality), each joined to the next. With --torus, also torus.ply:
6000 points of the torus around it (major radius 1, minor = the radius). With
--gap FRACTION, the torus points at angles in [0, FRACTION turn) are left out (missing
data) and ring_cut.ply is the ring without the nodes in that band.

  make_ring.py RADIUS [--torus] [--gap FRACTION]
"""
import math
import sys

radius = float(sys.argv[1])
gap = float(sys.argv[sys.argv.index("--gap") + 1]) if "--gap" in sys.argv else 0.0


def write_ring(name, kept):
    """The ring's nodes `kept` (indices), with the bones between consecutive kept nodes."""
    bones = [(kept.index(i), kept.index((i + 1) % 12)) for i in kept if (i + 1) % 12 in kept]
    with open(name, "w") as f:
        f.write(f"ply\nformat ascii 1.0\nelement vertex {len(kept)}\nproperty float x\nproperty float y\n"
                f"property float z\nproperty float quality\nelement edge {len(bones)}\nproperty int vertex1\n"
                "property int vertex2\nend_header\n")
        for i in kept:
            a = math.radians(30 * i)
            f.write(f"{math.cos(a):.6f} {math.sin(a):.6f} 0 {radius}\n")
        for a, b in bones:
            f.write(f"{a} {b}\n")


write_ring("ring.ply", list(range(12)))
if gap > 0:
    # Nodes inside the band, and the one at its start, go: the arc only spans the data.
    write_ring("ring_cut.ply", [i for i in range(12) if 30 * i >= 360 * gap])

if "--torus" in sys.argv:
    import numpy as np
    rng = np.random.default_rng(1)
    u, v = rng.uniform(0, 2 * np.pi, (2, 6000))
    ring = 1 + radius * np.cos(v)
    points = np.c_[ring * np.cos(u), ring * np.sin(u), radius * np.sin(v)]
    points = points[u >= 2 * np.pi * gap]
    with open("torus.ply", "w") as f:
        f.write(f"ply\nformat ascii 1.0\nelement vertex {len(points)}\nproperty float x\nproperty float y\n"
                "property float z\nend_header\n")
        np.savetxt(f, points, fmt="%.6f")
