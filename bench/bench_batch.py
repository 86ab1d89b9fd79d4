#!/usr/bin/python3
"""Batch throughput: 100 generated scans of 10K points (tori, Ys and bent tubes, each with
its own seed), skeletonized by the command line with --jobs 1 and --jobs 2, by Python's
skeletonize_files on its local process pool, and on a Dask LocalCluster of two one-thread
worker processes. Prints one row per way: wall seconds for the whole batch (median of
--repeats runs), scans per second, and the speed-up over --jobs 1.

    PYTHONPATH=build/python bench/bench_batch.py --cli build/cli/pcskeleton [--scans 100] [--repeats 3]

The scans are written to a temporary folder and removed afterwards.
"""

import argparse
import os
import shutil
import statistics
import subprocess
import tempfile
import time

import numpy as np

import pcskeleton


def tube(rng, start, end, radius, count):
    start, end = np.asarray(start, float), np.asarray(end, float)
    axis = end - start
    length = np.linalg.norm(axis)
    axis /= length
    side = np.cross(axis, [0.0, 0.0, 1.0] if abs(axis[2]) < 0.9 else [1.0, 0.0, 0.0])
    side /= np.linalg.norm(side)
    other = np.cross(axis, side)
    t = rng.uniform(0, length, count)
    angle = rng.uniform(0, 2 * np.pi, count)
    return start + np.outer(t, axis) + radius * (np.outer(np.cos(angle), side) + np.outer(np.sin(angle), other))


def scan(kind, seed, count=10000):
    rng = np.random.default_rng(seed)
    if kind == 0:  # a torus
        t, u = rng.uniform(0, 2 * np.pi, (2, count))
        r = 1 + 0.25 * np.cos(u)
        points = np.stack([r * np.cos(t), r * np.sin(t), 0.25 * np.sin(u)], 1)
    elif kind == 1:  # a Y
        centre = [0.0, 0.0, 0.0]
        ends = [[0, 0, -1.5], [1.0, 0, 1.0], [-1.0, 0, 1.0]]
        points = np.concatenate([tube(rng, centre, end, 0.12, count // 3) for end in ends])
    else:  # a tube bent at a right angle
        points = np.concatenate([tube(rng, [0, 0, 0], [2, 0, 0], 0.15, count // 2),
                                 tube(rng, [2, 0, 0], [2, 2, 0], 0.15, count - count // 2)])
    return points + rng.normal(0, 0.005, points.shape)


def timed(run, repeats, clean):
    seconds = []
    for _ in range(repeats):
        clean()
        start = time.perf_counter()
        run()
        seconds.append(time.perf_counter() - start)
    return statistics.median(seconds)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", required=True, help="the pcskeleton program")
    parser.add_argument("--scans", type=int, default=100)
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()

    work = tempfile.mkdtemp(prefix="bench_batch_")
    try:
        inputs = os.path.join(work, "scans")
        os.makedirs(inputs)
        for i in range(args.scans):
            pcskeleton.write_points(scan(i % 3, i), os.path.join(inputs, f"scan{i:03d}.ply"))
        out = os.path.join(work, "out")

        def clean():
            shutil.rmtree(out, ignore_errors=True)

        def cli(jobs):
            return lambda: subprocess.run([args.cli, inputs, "-O", out, "--jobs", str(jobs), "--quiet"], check=True)

        rows = [("pcskeleton --jobs 1", timed(cli(1), args.repeats, clean)),
                ("pcskeleton --jobs 2", timed(cli(2), args.repeats, clean)),
                ("skeletonize_files, local pool of 2",
                 timed(lambda: pcskeleton.skeletonize_files(inputs, out, jobs=2), args.repeats, clean))]
        try:
            import distributed
        except ImportError:
            distributed = None
        if distributed is not None:
            with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                          dashboard_address=None) as cluster, distributed.Client(cluster) as client:
                client.run(lambda: __import__("pcskeleton"))  # workers import the module once, as a pool's do
                rows.append(("skeletonize_files, Dask LocalCluster 2x1",
                             timed(lambda: pcskeleton.skeletonize_files(inputs, out, client=client), args.repeats, clean)))
        baseline = rows[0][1]
        print(f"{args.scans} scans of 10K points, {os.cpu_count()} cores, median of {args.repeats}")
        print(f"{'way':44s} {'seconds':>8s} {'scans/s':>8s} {'speed-up':>9s}")
        for name, seconds in rows:
            print(f"{name:44s} {seconds:8.2f} {args.scans / seconds:8.1f} {baseline / seconds:8.2f}x")
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
