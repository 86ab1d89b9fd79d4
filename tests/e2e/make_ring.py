#!/usr/bin/python3
"""Writes ring.ply: a skeleton of 12 nodes on the unit circle in the xy plane (node i at
30 i degrees, radius in quality), each joined to the next. With --torus, also torus.ply:
6000 points of the torus around it (major radius 1, minor = the radius).

  make_ring.py RADIUS [--torus]
"""
import math
import sys

radius = float(sys.argv[1])
with open("ring.ply", "w") as f:
    f.write("ply\nformat ascii 1.0\nelement vertex 12\nproperty float x\nproperty float y\n"
            "property float z\nproperty float quality\nelement edge 12\nproperty int vertex1\n"
            "property int vertex2\nend_header\n")
    for i in range(12):
        a = math.radians(30 * i)
        f.write(f"{math.cos(a):.6f} {math.sin(a):.6f} 0 {radius}\n")
    for i in range(12):
        f.write(f"{i} {(i + 1) % 12}\n")

if "--torus" in sys.argv:
    import numpy as np
    rng = np.random.default_rng(1)
    u, v = rng.uniform(0, 2 * np.pi, (2, 6000))
    ring = 1 + radius * np.cos(v)
    points = np.c_[ring * np.cos(u), ring * np.sin(u), radius * np.sin(v)]
    with open("torus.ply", "w") as f:
        f.write("ply\nformat ascii 1.0\nelement vertex 6000\nproperty float x\nproperty float y\n"
                "property float z\nend_header\n")
        np.savetxt(f, points, fmt="%.6f")
