#!/usr/bin/python3
"""A batch of scans on a Dask cluster: the skeleton of every point file of a folder.

    PYTHONPATH=build/python python3 python/examples/dask_batch.py SCANS_FOLDER OUT_FOLDER [SCHEDULER]

Without SCHEDULER a LocalCluster of two one-thread worker processes runs it; with one
(tcp://host:8786) the cluster behind it does. Every worker must see both folders at the
same paths. Prints each input as it is done, then the failures.
"""
import sys

import distributed

import pcskeleton


def main():
    scans, out = sys.argv[1], sys.argv[2]
    if len(sys.argv) > 3:
        client, cluster = distributed.Client(sys.argv[3]), None
    else:
        cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=None)
        client = distributed.Client(cluster)
    try:
        rows = pcskeleton.skeletonize_files(scans, out, client=client,
                                            progress=lambda percent, what: print(f"{percent:3d}% {what}"))
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    failed = [row for row in rows if row["status"] == "failed"]
    print(f"{len(rows) - len(failed)} of {len(rows)} inputs done or skipped; {len(failed)} failed")
    for row in failed:
        print(f"  {row['input']}: {row['message']}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
