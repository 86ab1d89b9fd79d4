#!/usr/bin/python3
"""Checks a contracted cloud written by meshlabserver against its input.

usage: check_contracted.py INPUT OUTPUT
Passes when OUTPUT has as many points as INPUT, all finite, near INPUT's bounding box
(contraction may push a thin tip slightly out, paper Fig. 4a, but never far) and
contracted: on average at least 2 input spacings away from the nearest input point.
"""
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../../scripts")
from render_points import read_points  # noqa: E402


def nearest_distances(queries, points, exclude_zero=False):
    out = np.empty(len(queries))
    for start in range(0, len(queries), 512):
        block = queries[start:start + 512]
        d2 = ((block[:, None, :] - points[None, :, :]) ** 2).sum(axis=2)
        if exclude_zero:
            d2[d2 == 0] = np.inf
        out[start:start + 512] = np.sqrt(d2.min(axis=1))
    return out


def main():
    source, result = read_points(sys.argv[1]), read_points(sys.argv[2])
    failures = []
    if len(source) != len(result):
        failures.append(f"{len(result)} points written for {len(source)} input points")
    if not np.isfinite(result).all():
        failures.append("non-finite coordinates")
    slack = 0.1 * np.linalg.norm(source.max(0) - source.min(0))
    if (result.min(0) < source.min(0) - slack).any() or (result.max(0) > source.max(0) + slack).any():
        failures.append("points far outside the input's bounding box")
    spacing = np.median(nearest_distances(source[::7], source, exclude_zero=True))
    depth = nearest_distances(result, source).mean()
    print(f"points {len(result)}, input spacing {spacing:.4g}, mean depth of contracted points {depth:.4g}")
    if not depth > 2 * spacing:
        failures.append(f"not contracted: mean depth {depth:.4g} <= 2 x spacing {spacing:.4g}")
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
