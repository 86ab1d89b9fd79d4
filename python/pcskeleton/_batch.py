"""Many scans at once: skeletonize_files, on a local process pool or on a Dask cluster.

The inputs and the names of their outputs follow the same rules as the command line's
``pcskeleton INPUT... -O FOLDER`` (the library's batch_files): folders give their point
files, globs their matches, and two inputs of one name get distinct outputs.
"""

import concurrent.futures
import functools
import multiprocessing
import os
import time

from . import _pcskeleton

SUMMARY_COLUMNS = ("input", "output", "points", "nodes", "cycles", "tips", "parts", "warnings", "seconds", "status",
                   "message")


def _row(path, output, **values):
    row = dict.fromkeys(SUMMARY_COLUMNS)
    row.update(input=path, output=output, **values)
    return row


def _skeletonize_one(path, output, parameters, force):
    """One input, in a worker: its skeleton written to `output`, and its summary row
    whatever happens (a failure is a row, never an exception)."""
    return _pcskeleton._as_batch_input(functools.partial(_skeletonize_and_write, path, output, parameters, force))


def _skeletonize_and_write(path, output, parameters, force):
    from . import read_points, skeletonize
    start = time.perf_counter()
    try:
        if os.path.exists(output) and not force:
            raise ValueError(f"'{output}' exists already; force=True replaces it.")
        points = read_points(path)
        skeleton = skeletonize(points, **parameters)
        skeleton.write(output)
        topology = skeleton.report["topology"]
        row = _row(path, output, points=len(points), nodes=topology["nodes"], cycles=topology["cycles"],
                   tips=topology["tips"], parts=topology["components"], warnings=len(skeleton.report["warnings"]),
                   status="ok", message="")
    except Exception as error:  # the input's failure, reported in its row; the batch goes on
        row = _row(path, output, status="failed", message=str(error))
    row["seconds"] = round(time.perf_counter() - start, 3)
    return row


def _lost(path, output, error):
    """The row of an input whose worker did not come back (it died, or the cluster lost it)."""
    return _row(path, output, status="failed", message=f"its worker failed: {type(error).__name__}: {error}")


def _collect(pending, completed, progress):
    """Each input's row as its future completes (`pending`: future -> (index, task)); a
    future that failed (its worker died, or the cluster lost it) gives a failed row."""
    for future in completed:
        index, task = pending[future]
        try:
            row = future.result()
        except Exception as error:
            row = _lost(task.args[0], task.args[1], error)
        progress(index, row)


def _run_locally(tasks, jobs, progress):
    # Processes started afresh ("spawn"), not forked: a fork of a process that has run
    # OpenMP (as any skeletonize call does) can hang in the child.
    context = multiprocessing.get_context("spawn")
    with concurrent.futures.ProcessPoolExecutor(max_workers=min(jobs, len(tasks)), mp_context=context) as pool:
        pending = {pool.submit(task): (index, task) for index, task in tasks}
        _collect(pending, concurrent.futures.as_completed(pending), progress)


def _run_on_dask(tasks, client, progress):
    try:
        import distributed
    except ImportError:
        raise ImportError("client= runs the batch on a Dask cluster, which needs Dask's distributed scheduler: "
                          "install python3-distributed (Debian) or `pip install distributed`.") from None
    pending = {client.submit(task, pure=False): (index, task) for index, task in tasks}
    _collect(pending, distributed.as_completed(list(pending)), progress)


def skeletonize_files(paths, out_dir, client=None, *, jobs=None, force=False, progress=None, **parameters):
    """The skeleton of each of many point files, written as ``<stem>_skeleton.ply`` into
    ``out_dir``; returns one summary row (a dict) per input, in the inputs' order.

    paths: files, folders (their point files, not subfolders') and globs ("scans/*.ply"),
        or one of them.
    out_dir: the folder for the skeletons (made if missing). Two inputs of one name in
        different folders are told apart by their folder (``a_scan``, ``b_scan``).
    client: None to run on this machine, one input per process (``jobs`` of them, by
        default one per core), or a ``distributed.Client`` to run on its Dask cluster
        (a LocalCluster, SLURM, Kubernetes...); every worker must see the inputs and
        ``out_dir`` at the same paths (a shared file system).
    force: redo an input whose skeleton exists already; without it the input is skipped,
        so that calling again resumes a batch.
    progress: None, or a callable(percent, message) called as each input is done.
    parameters: skeletonize's keywords, for every input; checked before any work.

    A row has input, output, points, nodes, cycles, tips, parts, warnings, seconds, status
    ('ok', 'failed' or 'skipped') and message (why it failed). One input's failure does not
    stop the others. With the local pool, call it from under ``if __name__ == "__main__":``
    in a script (its workers import the script afresh).
    """
    if isinstance(paths, (str, os.PathLike)):
        paths = [paths]
    inputs = _pcskeleton._expand_inputs([os.fspath(path) for path in paths])
    _pcskeleton._check_skeleton_parameters(parameters, "skeletonize_files")
    os.makedirs(out_dir, exist_ok=True)
    outputs = [os.path.join(os.fspath(out_dir), f"{stem}_skeleton.ply") for stem in _pcskeleton._output_stems(inputs)]
    # Each input's file (device and inode, as os.path.samefile compares them) looked up once:
    # outputs against inputs pairwise would grow with the square of the batch.
    input_files = {(status.st_dev, status.st_ino) for status in map(os.stat, filter(os.path.exists, inputs))}
    for output in filter(os.path.exists, outputs):
        status = os.stat(output)
        if (status.st_dev, status.st_ino) in input_files:
            raise ValueError(f"'{output}' would be written over an input; choose another out_dir.")

    rows = [None] * len(inputs)
    tasks = []
    for index, (path, output) in enumerate(zip(inputs, outputs)):
        if os.path.exists(output) and not force:
            rows[index] = _row(path, output, status="skipped", message="its skeleton exists already (force=True redoes it)")
        else:
            tasks.append((index, functools.partial(_skeletonize_one, path, output, parameters, force)))

    finished = sum(row is not None for row in rows)

    def record(index, row):
        nonlocal finished
        rows[index] = row
        finished += 1
        if progress is not None:
            progress(100 * finished // len(rows), f"{row['input']}: {row['status']}")

    if tasks and client is None:
        _run_locally(tasks, jobs or os.cpu_count() or 1, record)
    elif tasks:
        _run_on_dask(tasks, client, record)
    return rows
