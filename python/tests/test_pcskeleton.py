"""The Python module against known answers, the CLI, and its own promises.

Run by CTest (python_module) with PYTHONPATH=<build>/python and PCSKELETON_CLI set to the
command-line tool built beside it.
"""
import os
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import pcskeleton
import shapes


@pytest.fixture(scope="module")
def torus_points():
    return shapes.torus()


@pytest.fixture(scope="module")
def torus_skeleton(torus_points):
    return pcskeleton.skeletonize(torus_points)


# ---- Known answers -----------------------------------------------------------------------

def test_torus_has_one_cycle_and_every_point_a_node(torus_points, torus_skeleton):
    s = torus_skeleton
    assert s.report["topology"]["cycles"] == 1
    assert s.report["topology"]["components"] == 1
    assert s.report["topology"]["tips"] == 0
    assert s.nodes.shape == (len(s.radii), 3) and s.nodes.dtype == np.float64
    assert s.edges.shape[1] == 2 and s.edges.max() < len(s.nodes)
    assert s.correspondence.shape == (len(torus_points),)
    assert s.correspondence.min() >= 0 and s.correspondence.max() < len(s.nodes)
    assert s.contracted.shape == torus_points.shape
    # The nodes lie on the torus' centre circle, the radii near its tube radius.
    assert np.allclose(np.linalg.norm(s.nodes[:, :2], axis=1), 1.0, atol=0.05)
    assert np.allclose(s.radii, 0.25, rtol=0.1)


def test_y_has_three_tips_and_one_junction():
    s = pcskeleton.skeletonize(shapes.y_shape())
    t = s.report["topology"]
    assert (t["tips"], t["junctions"], t["cycles"], t["components"]) == (3, 1, 0, 1)


def test_a_bridged_gap_is_an_inferred_bone():
    # A tube with no points for a band across its middle: one skeleton, the bone across the
    # gap marked as inferred, every other bone not.
    rng = np.random.default_rng(5)
    angle, z = rng.uniform(0, 2 * np.pi, 8000), rng.uniform(0, 2, 8000)
    keep = (z < 0.9) | (z > 1.1)
    tube = np.column_stack([0.1 * np.cos(angle), 0.1 * np.sin(angle), z])[keep]
    s = pcskeleton.skeletonize(tube)
    assert s.report["topology"]["components"] == 1
    assert s.inferred.dtype == np.bool_ and s.inferred.shape == (len(s.edges),)
    assert s.inferred.sum() == 1
    a, b = s.nodes[s.edges[s.inferred][0]]
    assert min(a[2], b[2]) < 0.95 and max(a[2], b[2]) > 1.05  # it spans the gap
    assert not pcskeleton.Skeleton(s.nodes, s.edges).inferred.any()


def test_a_plate_gets_a_loop_around_each_hole_and_sheets_false_keeps_the_papers_thinning(torus_skeleton):
    plate = shapes.plate_with_two_holes()
    s = pcskeleton.skeletonize(plate)
    assert s.report["sheet_patches"] == 1
    assert s.report["topology"]["cycles"] == 2
    assert s.report["topology"]["tips"] <= 2
    off = pcskeleton.skeletonize(plate, sheets=False)
    assert off.report["sheet_patches"] == 0
    assert "Sheets: off." in off.report["text"]
    assert torus_skeleton.report["sheet_patches"] == 0


def test_facing_walls_are_counted_and_facing_walls_false_keeps_every_neighbour(torus_points):
    s = pcskeleton.skeletonize(torus_points)
    assert s.report["facing_neighbours_left_out"] >= 0
    assert "Facing walls: " in s.report["text"]
    off = pcskeleton.skeletonize(torus_points, facing_walls=False)
    assert off.report["facing_neighbours_left_out"] == -1
    assert "Facing walls: off." in off.report["text"]
    assert off.report["topology"]["cycles"] == 1


def test_medial_pull_keeps_the_loop_of_a_ring_with_a_narrow_hole_and_is_counted(torus_skeleton):
    thick_ring = shapes.torus(6000, major=0.5, minor=0.36)
    pulled = pcskeleton.skeletonize(thick_ring, medial_pull=1.0)
    assert pulled.report["medial_pull_points"] > len(thick_ring) // 2
    assert "Medial pull: " in pulled.report["text"]
    assert pulled.report["topology"]["cycles"] == 1
    assert torus_skeleton.report["medial_pull_points"] == -1
    assert "Medial pull" not in torus_skeleton.report["text"]


def test_noisy_y_keeps_three_tips():
    points = shapes.y_shape() + np.random.default_rng(3).normal(0, 0.005, (4500, 3))
    assert pcskeleton.skeletonize(points).report["topology"]["tips"] == 3


def test_outliers_get_no_node_and_are_reported(torus_points):
    rng = np.random.default_rng(4)
    outliers = rng.uniform(-1.3, 1.3, (40, 3))
    s = pcskeleton.skeletonize(np.concatenate([torus_points, outliers]))
    assert s.report["topology"]["cycles"] == 1
    assert s.report["outliers"] >= 30
    assert (s.correspondence[len(torus_points):] == -1).sum() >= 30
    kept = pcskeleton.skeletonize(np.concatenate([torus_points, outliers]), keep_outliers=True)
    assert (kept.correspondence >= 0).all()


def test_input_array_is_not_modified(torus_points):
    before = torus_points.copy()
    pcskeleton.skeletonize(torus_points)
    assert np.array_equal(before, torus_points)


# ---- Parameters ----------------------------------------------------------------------------

def test_version_is_the_projects():
    assert pcskeleton.__version__.count(".") == 2 and all(part.isdigit() for part in pcskeleton.__version__.split("."))
    # The command-line tool's is the same one.
    cli = subprocess.run([os.environ.get("PCSKELETON_CLI", "pcskeleton"), "--version"], capture_output=True, text=True)
    assert cli.stdout.strip() == f"pcskeleton {pcskeleton.__version__}", cli.stdout + cli.stderr


def test_every_keyword_is_documented_with_its_default():
    for name, value in pcskeleton.SKELETON_PARAMETERS.items():
        assert f"{name} [{value!r}]" in pcskeleton.skeletonize.__doc__
    for name, value in pcskeleton.RECONSTRUCTION_PARAMETERS.items():
        assert f"{name} [{value!r}]" in pcskeleton.reconstruct.__doc__


def test_keywords_reach_the_library(torus_points):
    one = pcskeleton.skeletonize(torus_points, iterations=1)
    assert one.report["convergence"]["iterations"] == 1
    assert one.report["convergence"]["stop_reason"] == "iteration_limit"
    assert any(w["kind"] == "iteration_limit" for w in one.report["warnings"])
    warning = next(w for w in one.report["warnings"] if w["kind"] == "iteration_limit")
    assert ("raise", "iterations") in warning["remedies"]  # the advice names the keyword
    coarse = pcskeleton.skeletonize(torus_points, radius=0.06)
    assert len(coarse.nodes) < len(pcskeleton.skeletonize(torus_points).nodes)


def test_paper_turns_the_added_steps_off_and_later_keywords_still_apply(torus_points):
    paper = pcskeleton.skeletonize(torus_points, paper=True)
    assert paper.report["outliers"] == 0
    assert "Refinement" not in paper.report["text"] or "off" in paper.report["text"]
    with_refine = pcskeleton.skeletonize(torus_points, paper=True, refine=True)
    assert with_refine.report["topology"]["cycles"] == 1


def test_multi_resolution_gives_every_point_a_node():
    points = shapes.torus(count=30000, seed=5)
    s = pcskeleton.skeletonize(points, contracted_points=8000)
    assert s.report["multi_resolution"] and s.report["contracted_points"] <= 8000
    assert s.report["topology"]["cycles"] == 1
    assert (s.correspondence >= 0).all() and len(s.correspondence) == len(points)
    with pytest.raises(ValueError, match="GB"):
        pcskeleton.skeletonize(points, full_resolution=True, memory_limit=0.01)


# ---- Errors ----------------------------------------------------------------------------------

@pytest.mark.parametrize("call, message", [
    (lambda: pcskeleton.skeletonize(np.zeros((3, 3))), "Too few points"),
    (lambda: pcskeleton.skeletonize(np.zeros((10, 2))), r"shape \(n, 3\)"),
    (lambda: pcskeleton.skeletonize(shapes.torus(500), iterations=0), "at least 1"),
    (lambda: pcskeleton.skeletonize(np.full((20, 3), np.nan)), "finite|NaN|not a number"),
    (lambda: pcskeleton.skeletonize(shapes.torus(500), loop_opening=-1), "^loop_opening must be 0"),
    (lambda: pcskeleton.skeletonize(shapes.torus(500), gap_stretch=0.5), "^gap_stretch must be 0"),
    (lambda: pcskeleton.read_points("/nonexistent/scan.ply"), "nonexistent"),
    (lambda: pcskeleton.read_skeleton("/nonexistent/skeleton.ply"), "nonexistent"),
    (lambda: pcskeleton.skeletonize(shapes.torus(500), wl=float("inf")), "^wl must be 0"),
    (lambda: pcskeleton.skeletonize(shapes.torus(500), sl=1e308), "^sl must be between 1 and 1000"),
    (lambda: pcskeleton.skeletonize(shapes.torus(500), threshold=float("inf")), "^threshold must be at least 0"),
    (lambda: pcskeleton.skeletonize(shapes.torus(500), outlier_isolation=float("nan")), "^outlier_isolation"),
    (lambda: pcskeleton.skeletonize(shapes.torus(500) * 1e154), "coordinates up to"),
    (lambda: pcskeleton.skeletonize(shapes.torus(500) * 1e-200), "span only"),
])
def test_bad_input_is_a_value_error_with_the_library_message(call, message):
    with pytest.raises(ValueError, match=message):
        call()


def test_unknown_keyword_or_wrong_type_is_a_type_error(torus_points):
    with pytest.raises(TypeError, match="unexpected keyword argument 'iteration'"):
        pcskeleton.skeletonize(torus_points, iteration=3)
    with pytest.raises(TypeError, match="iterations"):
        pcskeleton.skeletonize(torus_points, iterations="many")


@pytest.mark.parametrize("points, got", [
    ("scan.ply", "got str"),
    (None, "got NoneType"),
    (np.ones((20, 3), dtype=bool), "got an array of bool"),
    (np.ones((20, 3), dtype=complex), "got an array of complex128"),
    (np.array([[1.0, 2.0, "3"]] * 20, dtype=object), "got an array of object"),
])
def test_points_that_are_not_real_numbers_are_a_type_error_not_a_cast(points, got, torus_points, tmp_path):
    # numpy's cast would read True as 1 and drop an imaginary part with only a warning.
    message = "must be an array of real numbers; " + got
    with pytest.raises(TypeError, match=message):
        pcskeleton.skeletonize(points)
    with pytest.raises(TypeError, match=message):
        pcskeleton.write_points(points, str(tmp_path / "out.xyz"))
    assert not (tmp_path / "out.xyz").exists()
    skeleton = pcskeleton.skeletonize(torus_points)
    with pytest.raises(TypeError, match=message):
        pcskeleton.reconstruct(points, skeleton)
    with pytest.raises(TypeError, match="nodes " + message):
        pcskeleton.Skeleton(points, skeleton.edges)


def test_malformed_files_raise_value_error(tmp_path):
    bad = tmp_path / "bad.ply"
    bad.write_bytes(b"ply\nformat binary_little_endian 1.0\nelement vertex 1000000\n"
                    b"property float x\nproperty float y\nproperty float z\nend_header\n\x00\x01")
    with pytest.raises(ValueError):
        pcskeleton.read_points(str(bad))
    bad.write_bytes(b"ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nend_header\n1\nfoo\n")
    with pytest.raises(ValueError):
        pcskeleton.read_skeleton(str(bad))


# ---- Files and the CLI ------------------------------------------------------------------------

def test_same_skeleton_as_the_cli_byte_for_byte(tmp_path, torus_points):
    cloud = tmp_path / "torus.ply"
    pcskeleton.write_points(torus_points, str(cloud))
    from_cli = tmp_path / "cli.ply"
    subprocess.run([os.environ["PCSKELETON_CLI"], str(cloud), "-o", str(from_cli), "--quiet", "--radius", "0.03"],
                   check=True)
    from_python = tmp_path / "python.ply"
    pcskeleton.skeletonize(pcskeleton.read_points(str(cloud)), radius=0.03).write(str(from_python))
    assert from_cli.read_bytes() == from_python.read_bytes()


@pytest.mark.parametrize("extension", ["ply", "obj", "cg"])
def test_written_skeletons_read_back(tmp_path, torus_skeleton, extension):
    path = tmp_path / f"skeleton.{extension}"
    torus_skeleton.write(str(path))
    again = pcskeleton.read_skeleton(str(path))
    assert np.allclose(again.nodes, torus_skeleton.nodes, atol=1e-5)
    assert np.array_equal(again.edges, torus_skeleton.edges)
    if extension == "ply":
        assert np.allclose(again.radii, torus_skeleton.radii, rtol=1e-5)


def test_skeleton_from_arrays_is_checked():
    s = pcskeleton.Skeleton(np.eye(3), np.array([[0, 1], [1, 2]]), radii=np.ones(3))
    assert s.topology["tips"] == 2 and np.array_equal(s.radii, np.ones(3))
    # Without radii, as from an .obj file: estimated from the bones, positive.
    assert (pcskeleton.Skeleton(np.eye(3), np.array([[0, 1], [1, 2]])).radii > 0).all()
    with pytest.raises(ValueError, match="skeleton"):
        pcskeleton.Skeleton(np.eye(3), np.array([[0, 7]]))


@pytest.mark.parametrize("edges, message", [
    (np.array([[0, 2**32 + 1]]), "out of range"),         # numpy's cast to int would make it 1
    (np.array([[0.0, 1.9]]), "not a whole number"),        # and this 1
    (np.array([[0.0, np.nan]]), "not a whole number"),
    (np.array([[0, 2**64 - 1]], dtype=np.uint64), "out of range"),
    (np.array([["0", "1"]]), "array of integers"),
])
def test_skeleton_indices_are_never_wrapped_or_truncated(edges, message):
    with pytest.raises(ValueError, match=message):
        pcskeleton.Skeleton(np.eye(3), edges)


def test_skeleton_indices_of_any_integer_type_or_whole_floats_are_read():
    for edges in (np.array([[0, 1], [1, 2]], dtype=np.uint8), np.array([[0, 1], [1, 2]], dtype=np.int64),
                  np.array([[0.0, 1.0], [1.0, 2.0]]), [[0, 1], [1, 2]]):
        assert pcskeleton.Skeleton(np.eye(3), edges).topology["tips"] == 2
    with pytest.raises(ValueError, match="correspondence: 1.5 is not a valid index"):
        pcskeleton.Skeleton(np.eye(3), [[0, 1], [1, 2]], correspondence=np.array([0, 1.5]))


# ---- Step API, editing, reconstruction ---------------------------------------------------------

def test_contraction_step_by_step_gives_the_one_call_skeleton(torus_points, torus_skeleton):
    contraction = pcskeleton.Contraction(torus_points)
    reports = []
    while not contraction.finished:
        reports.append(contraction.iterate())
    assert contraction.stop_reason == "converged"
    assert [r["iteration"] for r in reports] == list(range(1, len(reports) + 1))
    assert reports[-1]["extent_ratio"] < 1
    assert contraction.contracted.shape == contraction.points.shape
    s = pcskeleton.skeleton_from_contraction(contraction)
    assert np.array_equal(s.nodes, torus_skeleton.nodes) and np.array_equal(s.edges, torus_skeleton.edges)


def test_thinning_keywords_tried_on_one_contraction_give_the_whole_runs_skeletons(torus_points, torus_skeleton):
    contraction = pcskeleton.Contraction(torus_points)
    while not contraction.finished:
        contraction.iterate()
    contracted = contraction.contracted.copy()
    for keywords in ({"node_spacing": 0.06}, {"refine": False, "recentre": False}):
        tried = pcskeleton.skeleton_from_contraction(contraction, **keywords)
        whole_run = pcskeleton.skeletonize(torus_points, **keywords)
        assert np.array_equal(tried.nodes, whole_run.nodes), keywords
        assert np.array_equal(tried.edges, whole_run.edges), keywords
        assert np.array_equal(tried.correspondence, whole_run.correspondence), keywords
    assert len(pcskeleton.skeleton_from_contraction(contraction, node_spacing=0.06).nodes) < len(torus_skeleton.nodes)
    # The contraction is not run again, and its own keywords are still the ones it was given.
    assert np.array_equal(contraction.contracted, contracted)
    again = pcskeleton.skeleton_from_contraction(contraction)
    assert np.array_equal(again.nodes, torus_skeleton.nodes) and np.array_equal(again.edges, torus_skeleton.edges)


def test_a_keyword_that_changes_the_contraction_is_refused_when_thinning_it(torus_points):
    contraction = pcskeleton.Contraction(torus_points, iterations=1)
    contraction.iterate()
    for name, value in (("k", 12), ("keep_outliers", True), ("contracted_points", 5000), ("paper", True)):
        with pytest.raises(TypeError, match=f"'{name}' changes the contraction: give it to Contraction"):
            pcskeleton.skeleton_from_contraction(contraction, **{name: value})
    with pytest.raises(TypeError, match="unexpected keyword argument 'resolution'"):
        pcskeleton.skeleton_from_contraction(contraction, resolution=64)
    with pytest.raises(TypeError, match="unexpected keyword argument 'node_spacingg'"):
        pcskeleton.skeleton_from_contraction(contraction, node_spacingg=0.05)
    with pytest.raises(ValueError, match="gap_limit"):
        pcskeleton.skeleton_from_contraction(contraction, gap_limit=-1)


def test_threads_sharing_one_contraction_take_turns():
    # Four threads iterating one contraction and reading it meanwhile: once a segfault.
    contraction = pcskeleton.Contraction(shapes.torus(count=3000, seed=9))
    errors, iterations = [], []

    def work():
        try:
            while not contraction.finished:
                iterations.append(contraction.iterate()["iteration"])
                assert contraction.contracted.shape == contraction.points.shape
                contraction.stop_reason
        except Exception as error:  # noqa: BLE001 (reported below, with the thread's error)
            errors.append(error)

    threads = [threading.Thread(target=work) for _ in range(4)]
    for thread in threads:
        thread.start()
    skeleton = pcskeleton.skeleton_from_contraction(contraction)  # meanwhile, from this thread
    for thread in threads:
        thread.join()
    assert not errors
    assert contraction.stop_reason == "converged"
    # One iteration after the other: none lost or run twice (a call after the last repeats it).
    last = max(iterations)
    assert sorted(set(iterations)) == list(range(1, last + 1))
    assert all(iterations.count(i) == 1 for i in range(1, last))
    assert len(skeleton.nodes) > 0
    assert pcskeleton.skeleton_from_contraction(contraction).topology["cycles"] == 1


def test_editor_operations_undo_and_redo(torus_skeleton):
    editor = pcskeleton.SkeletonEditor(torus_skeleton)
    a, b = torus_skeleton.edges[0]
    editor.delete_edge(int(a), int(b))
    assert editor.skeleton.topology["cycles"] == 0 and editor.can_undo
    merged = editor.merge_nodes([int(a), int(b)])
    assert editor.skeleton.topology["nodes"] == len(torus_skeleton.nodes) - 1 and merged >= 0
    editor.undo()
    editor.undo()
    assert np.array_equal(editor.skeleton.edges, torus_skeleton.edges) and not editor.can_undo
    editor.redo()
    assert editor.skeleton.topology["cycles"] == 0
    with pytest.raises(ValueError, match="does not exist"):
        editor.delete_nodes([10 ** 6])
    # The editor works on its own copy.
    assert torus_skeleton.topology["cycles"] == 1


def test_reconstruction_follows_the_skeleton(torus_points, torus_skeleton):
    vertices, faces, report = pcskeleton.reconstruct(torus_points, torus_skeleton, resolution=48)
    assert report["genus"] == 1 and report["components"] == 1 and report["closed"]
    assert faces.shape[1] == 3 and faces.max() < len(vertices)
    editor = pcskeleton.SkeletonEditor(torus_skeleton)
    editor.delete_edge(*map(int, torus_skeleton.edges[0]))
    _, _, cut = pcskeleton.reconstruct(torus_points, editor.skeleton, resolution=48)
    assert cut["genus"] == 0 and cut["components"] == 1


def test_reconstruction_fits_the_vertices_unless_asked_for_the_level_set(torus_points, torus_skeleton):
    vertices, faces, report = pcskeleton.reconstruct(torus_points, torus_skeleton, resolution=48)
    level_vertices, level_faces, level_report = pcskeleton.reconstruct(torus_points, torus_skeleton,
                                                                       resolution=48, level_set=True)
    assert "fit to the points:" in report["text"] and "fit to the points:" not in level_report["text"]
    assert np.array_equal(faces, level_faces) and not np.array_equal(vertices, level_vertices)
    assert level_report["genus"] == 1


def test_reconstruction_refuses_bad_parameters(torus_points, torus_skeleton):
    with pytest.raises(ValueError, match="resolution"):
        pcskeleton.reconstruct(torus_points, torus_skeleton, resolution=8)
    with pytest.raises(TypeError, match="unexpected keyword argument 'radius'"):
        pcskeleton.reconstruct(torus_points, torus_skeleton, radius=0.1)


# ---- Interop -----------------------------------------------------------------------------------

def _fork():
    """A stem from (0, 0, 0) to a fork at (0, 0, 1), a long arm to (0.6, 0, 1.6), a short
    one to (-0.3, 0, 1.3): nodes 0.1 apart along each."""
    nodes, edges = [(0.0, 0.0, 0.0)], []
    def chain(start, end, steps):
        first = len(nodes) - 1 if start is None else start
        previous = first
        a, b = np.array(nodes[first]), np.array(end)
        for i in range(1, steps + 1):
            nodes.append(tuple(a + (b - a) * i / steps))
            edges.append((previous, len(nodes) - 1))
            previous = len(nodes) - 1
        return previous
    fork = chain(0, (0, 0, 1), 10)
    long_tip = chain(fork, (0.6, 0, 1.6), 6)
    short_tip = chain(fork, (-0.3, 0, 1.3), 3)
    return pcskeleton.Skeleton(np.array(nodes), np.array(edges), np.full(len(nodes), 0.05)), fork, long_tip, short_tip


def test_branches_of_a_fork_have_their_lengths_orders_and_angles():
    skeleton, fork, long_tip, short_tip = _fork()
    branches = skeleton.branches
    assert len(branches) == 3
    assert list(branches.parent) == [-1, 0, 0]
    assert branches.base_node[0] == 0 and branches.tip_node[0] == fork
    by_tip = {int(t): i for i, t in enumerate(branches.tip_node)}
    long_arm, short_arm = by_tip[long_tip], by_tip[short_tip]
    assert branches.length[0] == pytest.approx(1.0)
    assert branches.length[long_arm] == pytest.approx(0.6 * 2 ** 0.5)
    assert branches.length[short_arm] == pytest.approx(0.3 * 2 ** 0.5)
    assert branches.order[long_arm] == 1 and branches.order[short_arm] == 2
    assert branches.angle_to_parent[long_arm] == pytest.approx(45.0)
    assert np.isnan(branches.angle_to_parent[0])
    assert list(branches.nodes[long_arm]) == [fork] + list(range(fork + 1, long_tip + 1))
    # The radius profile: one place and radius per node, from 0 at the base to the length.
    assert len(branches.profile_along[long_arm]) == len(branches.nodes[long_arm])
    assert branches.profile_along[long_arm][0] == 0.0
    assert branches.profile_along[long_arm][-1] == pytest.approx(branches.length[long_arm])
    assert np.allclose(branches.profile_radius[long_arm], 0.05)
    assert skeleton.branch_of(long_tip) == long_arm and skeleton.branch_of(fork) == 0
    from_tip = skeleton.measure_branches(up=(0, 0, -1))
    assert from_tip.base_node[0] == long_tip
    assert skeleton.measure_branches(root=fork).parent.tolist() == [-1, -1, -1]


def test_every_point_with_a_node_gets_a_branch_and_a_place(torus_points, torus_skeleton):
    branch, position = torus_skeleton.point_branches
    assert len(branch) == len(torus_points)
    with_node = torus_skeleton.correspondence >= 0
    assert (branch[with_node] >= 0).all() and (branch[~with_node] == -1).all()
    assert ((position[with_node] >= 0) & (position[with_node] <= 1)).all()
    assert torus_skeleton.branches.closes_loop.any(), "the torus's loop is closed by a branch"


def test_given_the_points_a_junctions_points_go_to_the_arm_they_lie_along():
    # A Y sampled as a tube: its junction node holds points of all three limbs.
    rng = np.random.default_rng(3)
    limbs = [((0, 0, 0), (0, 0, 1)), ((0, 0, 1), (-0.5, 0, 1.5)), ((0, 0, 1), (0.6, 0, 1.6))]
    points, limb_of = [], []
    for index, (a, b) in enumerate(limbs):
        a, b = np.array(a, float), np.array(b, float)
        axis = (b - a) / np.linalg.norm(b - a)
        side = np.cross(axis, (0, 1, 0)) if abs(axis[1]) < 0.9 else np.cross(axis, (1, 0, 0))
        side /= np.linalg.norm(side)
        other = np.cross(axis, side)
        t, angle = rng.random(2000), rng.random(2000) * 2 * np.pi
        ring = 0.06 * (np.cos(angle)[:, None] * side + np.sin(angle)[:, None] * other)
        points.append(a + t[:, None] * (b - a) + ring)
        limb_of += [index] * 2000
    points, limb_of = np.vstack(points), np.array(limb_of)
    skeleton = pcskeleton.skeletonize(points)
    by_node = skeleton.measure_branches().point_branch
    by_point = skeleton.measure_branches(points=points).point_branch
    tips = skeleton.measure_branches().tip_node
    # Each limb's branch: the one whose tip is nearest the limb's end (the stem's from the root).
    ends = [limbs[0][0], limbs[1][1], limbs[2][1]]
    nodes = skeleton.nodes
    branch_of_limb = [int(np.argmin([np.linalg.norm(nodes[t] - e) for t in tips])) for e in ends]
    branch_of_limb[0] = 0
    right = lambda branch: np.mean(branch == np.array(branch_of_limb)[limb_of])
    assert right(by_point) > 0.95 and right(by_point) > right(by_node) + 0.01, (right(by_point), right(by_node))
    with pytest.raises(ValueError, match="points must be the 6000 points the skeleton was computed from"):
        skeleton.measure_branches(points=points[:-1])


def test_branches_refuse_a_zero_up_axis_or_a_root_that_is_no_node():
    skeleton = _fork()[0]
    with pytest.raises(ValueError, match="The up axis has no length"):
        skeleton.measure_branches(up=(0, 0, 0))
    with pytest.raises(ValueError, match="is not a node of the skeleton"):
        skeleton.measure_branches(root=len(skeleton))
    with pytest.raises(ValueError, match="is not a node of the skeleton"):
        skeleton.branch_of(-1)


def test_branches_know_their_part_and_sum_up_per_part():
    # Two separate sticks: one branch each, in parts 0 and 1.
    nodes = [[0, 0, 0], [0, 0, 1], [5, 0, 0], [5, 0, 2]]
    skeleton = pcskeleton.Skeleton(nodes, [[0, 1], [2, 3]], radii=[0.1, 0.1, 0.2, 0.2])
    branches = skeleton.branches
    assert list(branches.part) == [0, 1]
    parts = branches.per_part()
    assert parts[0]["branches"] == 1 and parts[0]["length"] == pytest.approx(1.0)
    assert parts[1]["length"] == pytest.approx(2.0) and parts[1]["volume"] == pytest.approx(np.pi * 0.04 * 2)
    assert parts[1]["orders"] == {1: 1}
    assert "volume 0.282743" in repr(branches)


def test_branches_as_a_data_frame():
    pytest.importorskip("pandas")
    frame = _fork()[0].branches.to_pandas()
    assert list(frame.columns) == list(pcskeleton.Branches.COLUMNS) and len(frame) == 3


def test_networkx_graph(torus_skeleton):
    networkx = pytest.importorskip("networkx")
    graph = torus_skeleton.to_networkx()
    assert graph.number_of_nodes() == len(torus_skeleton.nodes)
    assert graph.number_of_edges() == len(torus_skeleton.edges)
    assert len(networkx.cycle_basis(graph)) == 1
    assert graph.nodes[0]["radius"] == pytest.approx(torus_skeleton.radii[0])


def test_open3d_line_set_and_point_cloud_input(torus_points, torus_skeleton):
    open3d = pytest.importorskip("open3d")
    lines = torus_skeleton.to_open3d()
    assert len(lines.lines) == len(torus_skeleton.edges) and len(lines.points) == len(torus_skeleton.nodes)
    cloud = open3d.geometry.PointCloud(open3d.utility.Vector3dVector(torus_points))
    from_open3d = pcskeleton.skeletonize(cloud)
    assert np.array_equal(from_open3d.edges, torus_skeleton.edges)


# ---- Progress, threads, memory -------------------------------------------------------------------

def test_progress_is_reported_and_its_exception_raised(torus_points):
    seen = []
    pcskeleton.skeletonize(torus_points, progress=lambda percent, message: seen.append((percent, message)))
    assert seen and seen[-1][0] == 100 and all(isinstance(m, str) for _, m in seen)

    def stop(percent, message):
        raise KeyboardInterrupt
    with pytest.raises(KeyboardInterrupt):
        pcskeleton.skeletonize(torus_points, progress=stop)


def test_the_gil_is_released_during_the_work():
    # This thread counts its turns while the worker is inside the library, outside its
    # progress callback. With the GIL held there, it would get a turn only when the worker
    # lets the GIL go at a callback's start: at most one per report. Released, it gets a
    # turn every few milliseconds for as long as the work lasts, however busy the machine.
    points = shapes.torus(count=12000, seed=6)
    state = {"in_callback": False, "reports": 0}
    done = threading.Event()

    def progress(percent, message):
        state["in_callback"] = True
        state["reports"] += 1
        state["in_callback"] = False

    worker = threading.Thread(target=lambda: (pcskeleton.skeletonize(points, progress=progress), done.set()))
    turns_inside = 0
    worker.start()
    while not done.is_set():
        if state["reports"] > 0 and not state["in_callback"]:
            turns_inside += 1
        time.sleep(0.001)
    worker.join()
    assert turns_inside > 2 * state["reports"] + 10, (turns_inside, state["reports"])


def resident_megabytes():
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * os.sysconf("SC_PAGE_SIZE") / 1e6


def test_no_memory_growth_over_repeated_calls():
    points = shapes.torus(count=2000, seed=7)
    # The warm-up makes every call the measured loop makes, so that first-use costs
    # (networkx's import, about 9 MB) are not counted as growth.
    for _ in range(10):
        s = pcskeleton.skeletonize(points)
        _ = (s.nodes, s.edges, s.correspondence, s.contracted, s.report, s.to_networkx())
    before = resident_megabytes()
    for _ in range(100):
        s = pcskeleton.skeletonize(points)
        _ = (s.nodes, s.edges, s.correspondence, s.contracted, s.report, s.to_networkx())
    growth = resident_megabytes() - before
    # One call's arrays are about 0.1 MB: a leak of them would pass 10 MB.
    assert growth < 5, f"{growth:.1f} MB more after 100 calls"


def _run_example(name, tmp_path):
    """Runs python/examples/NAME on its default input; returns its output and its picture."""
    pytest.importorskip("matplotlib")
    example = os.path.join(os.path.dirname(__file__), "..", "examples", name)
    picture = tmp_path / "picture.png"
    run = subprocess.run([sys.executable, example, "", str(picture)], capture_output=True, text=True, cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    return run.stdout, picture


def test_the_readme_example_draws_its_picture(tmp_path):
    output, picture = _run_example("skeleton_picture.py", tmp_path)
    assert "Skeleton: " in output and picture.stat().st_size > 10000


def test_the_branches_example_colours_the_corn_by_branch(tmp_path):
    output, picture = _run_example("branches_picture.py", tmp_path)
    assert "<pcskeleton.Branches: " in output and "branch 0: order 1" in output
    assert picture.stat().st_size > 10000


def test_skeleton_arrays_are_read_only_views_that_keep_it_alive(torus_points):
    s = pcskeleton.skeletonize(torus_points)
    nodes, edges = s.nodes, s.edges
    assert not nodes.flags.writeable and not edges.flags.writeable
    with pytest.raises(ValueError):
        nodes[0, 0] = 5.0
    assert np.shares_memory(s.nodes, nodes)  # the same storage each time: no copy
    expected = nodes.copy()
    del s
    assert np.array_equal(nodes, expected) and edges.max() < len(nodes)
