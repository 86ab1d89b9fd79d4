"""Batches: a Skeleton pickles exactly; skeletonize_files on a local process pool and on a
Dask LocalCluster gives the same files as one run after another; one bad input is a
failed row, never a failed batch; a rerun skips what is done."""

import filecmp
import os
import pickle
import subprocess
import sys

import numpy as np
import pytest

import pcskeleton
import shapes


@pytest.fixture(scope="module")
def scans(tmp_path_factory):
    """Five tori of 1500 points (one cycle each) and one file that is no point cloud."""
    folder = tmp_path_factory.mktemp("scans")
    for i in range(5):
        pcskeleton.write_points(shapes.torus(count=1500, seed=i), str(folder / f"torus{i}.xyz"))
    (folder / "broken.xyz").write_text("these are not\npoints\n")
    return folder


def test_a_skeleton_pickles_exactly(tmp_path):
    skeleton = pcskeleton.skeletonize(shapes.y_shape(count=3000))
    data = pickle.dumps(skeleton)
    copy = pickle.loads(data)
    assert pickle.dumps(copy) == data
    for name in ("nodes", "edges", "radii", "correspondence", "contracted", "inferred"):
        np.testing.assert_array_equal(getattr(copy, name), getattr(skeleton, name))
    assert copy.report == skeleton.report
    skeleton.write(str(tmp_path / "a.ply"))
    copy.write(str(tmp_path / "b.ply"))
    assert filecmp.cmp(tmp_path / "a.ply", tmp_path / "b.ply", shallow=False)
    # A skeleton read from a file has no contracted points: still exact.
    read = pcskeleton.read_skeleton(str(tmp_path / "a.ply"))
    assert pickle.dumps(pickle.loads(pickle.dumps(read))) == pickle.dumps(read)


def test_a_corrupt_pickle_is_refused_by_name():
    with pytest.raises(ValueError, match="pickled"):
        pcskeleton.Skeleton.__new__(pcskeleton.Skeleton).__setstate__((1, 2))


def _statuses(rows):
    return {os.path.basename(row["input"]): row["status"] for row in rows}


def test_local_batch_reports_the_bad_file_and_skips_on_rerun(scans, tmp_path):
    out = tmp_path / "out"
    rows = pcskeleton.skeletonize_files([str(scans)], str(out), jobs=2)
    assert [os.path.basename(r["input"]) for r in rows] == ["broken.xyz"] + [f"torus{i}.xyz" for i in range(5)]
    assert _statuses(rows) == {"broken.xyz": "failed", **{f"torus{i}.xyz": "ok" for i in range(5)}}
    broken = rows[0]
    assert "broken.xyz" in broken["message"] and broken["nodes"] is None
    for row in rows[1:]:
        assert row["points"] == 1500 and row["cycles"] == 1 and row["parts"] == 1 and row["seconds"] > 0
        assert pcskeleton.read_skeleton(row["output"]).topology["cycles"] == 1
    assert sorted(os.listdir(out)) == [f"torus{i}_skeleton.ply" for i in range(5)]

    again = pcskeleton.skeletonize_files(str(scans), str(out))
    assert _statuses(again) == {"broken.xyz": "failed", **{f"torus{i}.xyz": "skipped" for i in range(5)}}
    redone = pcskeleton.skeletonize_files(str(scans / "torus0.xyz"), str(out), force=True)
    assert _statuses(redone) == {"torus0.xyz": "ok"}


def test_bad_requests_are_refused_before_any_work(scans, tmp_path):
    with pytest.raises(TypeError, match="no_such_keyword"):
        pcskeleton.skeletonize_files(str(scans), str(tmp_path / "a"), no_such_keyword=1)
    with pytest.raises(ValueError, match="matches no file"):
        pcskeleton.skeletonize_files(str(scans / "*.nothing"), str(tmp_path / "b"))
    assert not (tmp_path / "a").exists() and not (tmp_path / "b").exists()
    # An input that is another input's output: refused, and both files are left as they were.
    folder = tmp_path / "same"
    folder.mkdir()
    pcskeleton.write_points(shapes.torus(count=1500, seed=0), str(folder / "ring.xyz"))
    (folder / "ring_skeleton.ply").write_text("not written over\n")
    with pytest.raises(ValueError, match="would be written over an input"):
        pcskeleton.skeletonize_files([str(folder / "ring.xyz"), str(folder / "ring_skeleton.ply")], str(folder), force=True)
    assert (folder / "ring_skeleton.ply").read_text() == "not written over\n"


def test_the_module_imports_without_dask_and_says_what_to_install(scans, tmp_path):
    # In a fresh interpreter where importing distributed fails, as on a machine without it.
    script = f"""
import sys
class NoDask:
    def find_spec(self, name, path=None, target=None):
        if name.split('.')[0] in ('dask', 'distributed'):
            raise ImportError('no ' + name)
sys.meta_path.insert(0, NoDask())
import pcskeleton
try:
    pcskeleton.skeletonize_files({str(scans / 'torus0.xyz')!r}, {str(tmp_path / 'out')!r}, client=object())
except ImportError as error:
    print(error)
"""
    result = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=True)
    assert "install python3-distributed" in result.stdout, result.stdout + result.stderr


def test_dask_local_cluster_gives_the_serial_runs_files(scans, tmp_path):
    distributed = pytest.importorskip("distributed")
    serial = tmp_path / "serial"
    serial_rows = pcskeleton.skeletonize_files(str(scans), str(serial), jobs=1)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        rows = pcskeleton.skeletonize_files(str(scans), str(tmp_path / "dask"), client=client)
    assert _statuses(rows) == _statuses(serial_rows)
    assert "broken.xyz" in rows[0]["message"]
    for name in (f"torus{i}_skeleton.ply" for i in range(5)):
        assert filecmp.cmp(serial / name, tmp_path / "dask" / name, shallow=False), name


def test_the_dask_example_runs_the_batch_and_lists_the_failure(scans, tmp_path):
    pytest.importorskip("distributed")
    example = os.path.join(os.path.dirname(__file__), "..", "examples", "dask_batch.py")
    run = subprocess.run([sys.executable, example, str(scans), str(tmp_path / "out")], capture_output=True, text=True)
    assert run.returncode == 1, run.stdout + run.stderr
    assert "5 of 6 inputs done or skipped; 1 failed" in run.stdout and "broken.xyz" in run.stdout, run.stdout
    assert len(list((tmp_path / "out").glob("*_skeleton.ply"))) == 5


def test_an_input_whose_worker_died_is_a_failed_row():
    # What a pool whose process was killed (or a cluster that lost its worker) hands back.
    import concurrent.futures
    import concurrent.futures.process
    import functools
    from pcskeleton import _batch
    future = concurrent.futures.Future()
    future.set_exception(concurrent.futures.process.BrokenProcessPool("a process was terminated abruptly"))
    task = functools.partial(_batch._skeletonize_one, "scans/a.ply", "out/a_skeleton.ply", {}, False)
    rows = {}
    _batch._collect({future: (3, task)}, [future], rows.__setitem__)
    assert rows[3]["status"] == "failed" and rows[3]["input"] == "scans/a.ply"
    assert "BrokenProcessPool" in rows[3]["message"] and "terminated abruptly" in rows[3]["message"]
