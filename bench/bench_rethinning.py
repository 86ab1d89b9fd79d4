#!/usr/bin/python3
"""Trying thinning's parameters in a notebook: the time of a whole skeletonize() call against
skeleton_from_contraction() with a new node spacing on a contraction already made, on tori
of growing size (the right answer is one cycle). Median of --repeats calls each, in one
process, after one untimed call of each (so that neither pays for the first touch of memory).

    PYTHONPATH=build/python bench/bench_rethinning.py [--sizes 10000 100000] [--repeats 5]
"""

import argparse
import statistics
import time

import numpy as np

import pcskeleton


def torus(count, seed=1, major=1.0, minor=0.3):
    rng = np.random.default_rng(seed)
    u, v = rng.uniform(0, 2 * np.pi, (2, count))
    ring = major + minor * np.cos(v)
    return np.column_stack([ring * np.cos(u), ring * np.sin(u), minor * np.sin(v)])


def median_seconds(call, repeats):
    call()
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        result = call()
        times.append(time.perf_counter() - start)
    return statistics.median(times), result


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[10000, 100000])
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()

    spacing = 0.03
    print(f"node spacing {pcskeleton.SKELETON_PARAMETERS['node_spacing']} -> {spacing}; median of "
          f"{args.repeats} calls; seconds")
    print(f"{'points':>10} {'skeletonize':>12} {'re-thinning':>12} {'ratio':>7} {'cycles':>7}")
    for size in args.sizes:
        points = torus(size)
        whole, _ = median_seconds(lambda: pcskeleton.skeletonize(points, node_spacing=spacing), args.repeats)
        contraction = pcskeleton.Contraction(points)
        while not contraction.finished:
            contraction.iterate()
        again, skeleton = median_seconds(
            lambda: pcskeleton.skeleton_from_contraction(contraction, node_spacing=spacing), args.repeats)
        print(f"{size:>10} {whole:>12.3f} {again:>12.3f} {whole / again:>6.1f}x {skeleton.topology['cycles']:>7}")


if __name__ == "__main__":
    main()
