#!/usr/bin/python3
"""Finds the Edit Skeleton tool's nodes in a screenshot of MeshLab (1280x900 window at the
top left): yellow discs are nodes, red ones selected nodes.

  find_nodes.py SCREENSHOT count             prints "<yellow> <red>"
  find_nodes.py SCREENSHOT position ANGLE    prints "x y" of the node seen at ANGLE degrees
                                             (counter-clockwise from +x) around the ring's
                                             centre, taken from the first screenshot with
                                             12 nodes (saved beside it as ring_centre.txt)
"""
import math
import os
import sys

import numpy as np
from PIL import Image

VIEW = (slice(75, 775), slice(0, 858))  # the 3D view, without toolbar icons or the info panel


def blobs(mask):
    """Centroids (x, y) of the 8-connected groups of at least 6 pixels."""
    seen = np.zeros_like(mask, dtype=bool)
    found = []
    for y, x in zip(*np.nonzero(mask)):
        if seen[y, x]:
            continue
        stack, pixels = [(y, x)], []
        seen[y, x] = True
        while stack:
            cy, cx = stack.pop()
            pixels.append((cy, cx))
            for dy in (-1, 0, 1):
                for dx in (-1, 0, 1):
                    ny, nx = cy + dy, cx + dx
                    if 0 <= ny < mask.shape[0] and 0 <= nx < mask.shape[1] and mask[ny, nx] and not seen[ny, nx]:
                        seen[ny, nx] = True
                        stack.append((ny, nx))
        if len(pixels) >= 6:
            ys, xs = zip(*pixels)
            found.append((np.mean(xs) + VIEW[1].start, np.mean(ys) + VIEW[0].start))
    return found


def nodes(path):
    rgb = np.asarray(Image.open(path).convert("RGB"))[VIEW].astype(int)
    r, g, b = rgb[..., 0], rgb[..., 1], rgb[..., 2]
    yellow = (r > 150) & (g > 110) & (b < 80) & (r - g < 90)
    red = (r > 150) & (g < 70) & (b < 70)
    return blobs(yellow), blobs(red)


def main():
    path, command = sys.argv[1], sys.argv[2]
    yellow, red = nodes(path)
    centre_file = os.path.join(os.path.dirname(path), "ring_centre.txt")
    if command == "count":
        if len(yellow) == 12 and not red and not os.path.exists(centre_file):
            cx, cy = np.mean(yellow, axis=0)
            open(centre_file, "w").write(f"{cx} {cy}\n")
        print(len(yellow), len(red))
        return 0
    cx, cy = (float(v) for v in open(centre_file).read().split())
    wanted = float(sys.argv[3])
    best = None
    for x, y in yellow + red:
        angle = math.degrees(math.atan2(cy - y, x - cx)) % 360  # screen y grows downwards
        gap = min(abs(angle - wanted), 360 - abs(angle - wanted))
        if gap < 10 and (best is None or gap < best[0]):
            best = (gap, x, y)
    if best is None:
        print(f"no node at {wanted} degrees", file=sys.stderr)
        return 1
    print(round(best[1]), round(best[2]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
