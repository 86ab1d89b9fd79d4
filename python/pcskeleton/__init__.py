"""Curve skeletons of point clouds by Laplacian-based contraction.

After "Point Cloud Skeletons via Laplacian-Based Contraction" (Cao, Tagliasacchi, Olson,
Zhang, Su; SMI 2010), with the steps this project added for imperfect scans (outlier
detection, denoising, facing walls kept apart, sheets' medial axes, re-centring, refinement,
tip extension, gap bridging) on by default and ``paper=True`` for the paper's pipeline
exactly. The same library as the ``pcskeleton`` command-line tool and the MeshLab plugins.

    >>> import pcskeleton
    >>> points = pcskeleton.read_points("scan.ply")            # (n, 3) float64
    >>> skeleton = pcskeleton.skeletonize(points)
    >>> skeleton.nodes, skeleton.edges, skeleton.radii          # (N, 3), (E, 2), (N,)
    >>> skeleton.correspondence                                # node per point, -1 for none
    >>> print(skeleton.report["text"])                         # cycles, tips, warnings
    >>> skeleton.write("scan_skeleton.ply")                    # also .obj, .cg
    >>> graph = skeleton.to_networkx()                         # needs networkx
    >>> rows = pcskeleton.skeletonize_files("scans/", "out/")  # many files, one per core

Errors in the input (a file that is not a point cloud, too few points, a parameter out of
range) raise ``ValueError`` with the library's message, which names the keyword to turn.
Every length is relative to the cloud's bounding-box diagonal: the same call works in
millimetres or kilometres.
"""

import textwrap

from . import _pcskeleton
from ._pcskeleton import __version__
from ._pcskeleton import Skeleton, SkeletonEditor, read_points, read_skeleton, write_points, write_mesh

__all__ = [
    "skeletonize", "Contraction", "skeleton_from_contraction", "reconstruct",
    "Skeleton", "SkeletonEditor", "read_points", "read_skeleton", "write_points", "write_mesh",
    "SKELETON_PARAMETERS", "RECONSTRUCTION_PARAMETERS", "Branches", "skeletonize_files",
]

# The defaults, read from the library itself (the CLI's and the MeshLab dialog's too).
SKELETON_PARAMETERS = _pcskeleton.skeleton_defaults()
RECONSTRUCTION_PARAMETERS = _pcskeleton.reconstruction_defaults()

# What each keyword does and which way to turn it, from the library's parameter table (the
# CLI's options and the MeshLab dialogs say the same); common keywords first.
_PAPER_HELP = {
    False: "the paper's pipeline exactly: no outlier detection, denoising, facing walls, link limit, sheets' "
           "medial axes, re-centring, refinement, gap bridging, tip extension or subsampling, and the paper's "
           "automatic k; every other keyword given still applies on top (paper=True, refine=True is the paper "
           "plus refinement).",
    True: "the paper's plain fit with uniform point weights and the zero level set as it is; every other keyword "
          "given still applies on top.",
}


def _describe(help_table, defaults, reconstruction):
    rows = [("paper", _PAPER_HELP[reconstruction], False)]
    rows += [(name, text, advanced) for name, (text, advanced) in help_table.items()]
    rows.sort(key=lambda row: row[2])  # stable: the table's order, common keywords first
    return "\n".join(textwrap.fill(f"{name} [{defaults[name]!r}]: {text}" + (" (advanced)" if advanced else ""),
                                   width=88, initial_indent="    ", subsequent_indent="        ")
                     for name, text, advanced in rows)


def _points_of(points):
    """An (n, 3) float64 array from a numpy-like array or an Open3D PointCloud."""
    if hasattr(points, "points") and type(points).__module__.startswith("open3d"):
        import numpy
        return numpy.asarray(points.points, dtype=numpy.float64)
    return points


def skeletonize(points, *, progress=None, **parameters):
    return _pcskeleton._skeletonize(_points_of(points), parameters, progress)


skeletonize.__doc__ = f"""The curve skeleton of a point cloud: contraction, thinning, embedding.

    points: an (n, 3) array (converted to float64) or an Open3D PointCloud; never modified.
    progress: None, or a callable(percent, message) called as the work goes on. An
        exception it raises is re-raised when the work is done.
    parameters: keywords, each as the CLI's option of the same name [default]; None means the
        default (radius, the node spacing's former name, is still accepted):

{_describe(_pcskeleton.skeleton_help(), SKELETON_PARAMETERS, False)}

    Returns a Skeleton: nodes (N, 3), edges (E, 2), radii (N,), correspondence (n,) (the
    node of each input point, -1 for none, e.g. an outlier), contracted (n, 3) and report,
    a dict: topology (nodes, edges, components, cycles, tips, junctions), convergence,
    warnings (each a kind, a message and remedies as (verb, keyword) pairs), text (the
    report as the CLI prints it).

    Raises ValueError for input the library cannot use (with its reason and remedy) and
    TypeError for an unknown keyword or a value of the wrong type. The work runs without
    the GIL: other Python threads keep running.
    """


class Contraction(_pcskeleton._Contraction):
    """The contraction step by step (paper steps 1-3), to watch or stop it early.

        c = Contraction(points, iterations=20)
        while not c.finished:
            print(c.iterate())          # iteration, extent_ratio, contraction_weight, seconds
        skeleton = skeleton_from_contraction(c)

    Keywords as skeletonize's (thinning's are kept for skeleton_from_contraction). Above
    contracted_points points, a spread subsample is contracted: `points` is what is
    contracted (the subsample, or every point) and `contracted` where it went, same order.
    `stop_reason` is 'not_stopped', 'converged', 'iteration_limit' or 'numerical_failure'.
    """

    def __init__(self, points, *, progress=None, **parameters):
        super().__init__(_points_of(points), parameters, progress)


def skeleton_from_contraction(contraction, *, progress=None, **parameters):
    """Thinning and embedding (paper steps 4-5) of a Contraction's current state, then the
    steps after them, with the keywords the Contraction was given. Every input point gets
    its node, also through a subsample.

    Thinning's keywords given here (node_spacing, refine, recentre, gap_limit, ...) replace
    the Contraction's for this call only, so trying them costs thinning alone, not the
    contraction again:

        c = Contraction(points)
        while not c.finished:
            c.iterate()
        for spacing in (0.02, 0.03, 0.05):
            print(spacing, skeleton_from_contraction(c, node_spacing=spacing).topology)

    A keyword that changes the contraction (k, wl, keep_outliers, contracted_points, paper,
    ...) raises TypeError: give it to a new Contraction."""
    return contraction._skeleton(progress, parameters)


def reconstruct(points, skeleton, *, progress=None, **parameters):
    return _pcskeleton._reconstruct(_points_of(points), skeleton, parameters, progress)


reconstruct.__doc__ = f"""A closed surface through the points whose inside and topology follow the
    skeleton (paper Sec. V): one component per skeleton component, genus = its cycles.

    points: the scan the skeleton belongs to, (n, 3) or an Open3D PointCloud.
    skeleton: a Skeleton with radii (skeletonize's, read_skeleton's of a .ply, or edited).
    parameters [default]:

{_describe(_pcskeleton.reconstruction_help(), RECONSTRUCTION_PARAMETERS, True)}

    Returns (vertices (V, 3), faces (F, 3), report): faces counter-clockwise seen from
    outside; report a dict with genus, components, closed, warnings and text.
    """


def _to_networkx(self):
    """A networkx.Graph: one node per skeleton node (attributes position and radius), one
    edge per bone (attribute length)."""
    import networkx
    import numpy
    graph = networkx.Graph()
    nodes, radii = self.nodes, self.radii
    for i, position in enumerate(nodes):
        attributes = {"position": tuple(position)}
        if len(radii):
            attributes["radius"] = float(radii[i])
        graph.add_node(i, **attributes)
    for a, b in self.edges:
        graph.add_edge(int(a), int(b), length=float(numpy.linalg.norm(nodes[a] - nodes[b])))
    return graph


def _to_open3d(self):
    """An open3d.geometry.LineSet of the nodes and bones."""
    import numpy
    import open3d
    lines = open3d.geometry.LineSet()
    # Open3D copies from writable arrays only; the skeleton's views are read-only.
    lines.points = open3d.utility.Vector3dVector(numpy.array(self.nodes))
    lines.lines = open3d.utility.Vector2iVector(numpy.array(self.edges).reshape(-1, 2))
    return lines


def _repr(self):
    t = self.topology
    return (f"<pcskeleton.Skeleton: {t['nodes']} nodes, {t['edges']} edges, {t['components']} "
            f"component(s), {t['cycles']} cycle(s), {t['tips']} tip(s)>")


class Branches:
    """The skeleton as branches: chains of bones between tips and junctions (or whole
    loops), grown from each part's root, by default its lowest node along ``up``.

    Orders follow the botanists' convention: 1 for the main axis from the root, 2 for what
    grows from it, ...; at each junction the main axis goes on into the child with the
    longest continuation. One value per branch in each column (numpy arrays): ``parent``
    (-1 from the root), ``order``, ``base_node``, ``tip_node``, ``length`` (along the
    bones), ``chord``, ``base_radius``, ``tip_radius``, ``mean_radius``, ``volume`` (the
    bones as truncated cones), ``angle_to_parent`` (degrees, 0 straight on; NaN from the
    root), ``points``, ``closes_loop``, ``part`` (the skeleton's connected part, from 0);
    ``nodes``, a list of each branch's nodes from base to tip, and its radius profile:
    ``profile_along`` (each node's distance from the base along the branch) and
    ``profile_radius`` (the branch's radius there), lists of arrays. Per input point,
    ``point_branch`` (-1 for none) and ``point_position`` (0 at the branch's base, 1 at its
    tip); per skeleton node, ``node_branch``.
    """

    COLUMNS = ("parent", "order", "base_node", "tip_node", "length", "chord", "base_radius", "tip_radius",
               "mean_radius", "volume", "angle_to_parent", "points", "closes_loop", "part")

    def __init__(self, table):
        for name, value in table.items():
            setattr(self, name, value)

    def __len__(self):
        return len(self.parent)

    def __repr__(self):
        orders = {}
        for order in self.order:
            orders[int(order)] = orders.get(int(order), 0) + 1
        by_order = ", ".join(f"order {o}: {n}" for o, n in sorted(orders.items()))
        return (f"<pcskeleton.Branches: {len(self)} ({by_order}), {float(sum(self.length)):.6g} long in all, "
                f"volume {float(sum(self.volume)):.6g}>")

    def per_part(self):
        """Per connected part of the skeleton: {part: {"branches", "length", "volume",
        "orders": {order: count}}}, the totals of its branches."""
        parts = {}
        for part, order, length, volume in zip(self.part, self.order, self.length, self.volume):
            totals = parts.setdefault(int(part), {"branches": 0, "length": 0.0, "volume": 0.0, "orders": {}})
            totals["branches"] += 1
            totals["length"] += float(length)
            totals["volume"] += float(volume)
            totals["orders"][int(order)] = totals["orders"].get(int(order), 0) + 1
        return parts

    def to_pandas(self):
        """A pandas.DataFrame, one row per branch (index: the branch number)."""
        import pandas
        return pandas.DataFrame({name: getattr(self, name) for name in self.COLUMNS})


def _measure_branches(self, up=(0.0, 0.0, 1.0), root=None, points=None):
    """The skeleton's branches (see Branches): each part grows from its lowest node along
    ``up``, except the part holding node ``root``, which grows from it. With ``points``,
    the (N, 3) points the skeleton was computed from, each point of a junction goes to the
    branch it lies along; without, to the branch that reaches the junction. A zero ``up``,
    a root that is not a node, or points that are not the skeleton's raise ValueError."""
    import numpy
    axis = numpy.asarray(up, dtype=numpy.float64).reshape(-1, 3)
    if points is not None:
        points = numpy.asarray(points, dtype=numpy.float64)
    return Branches(self._measure_branches(axis, -1 if root is None else int(root), points))


def _branches(self):
    """The branches with the default root (each part's lowest node along z); see
    measure_branches to choose another."""
    return self.measure_branches()


def _point_branches(self):
    """(branch, position) per input point: its branch (-1 for none) and its place along it,
    0 at the base and 1 at the tip."""
    branches = self.measure_branches()
    return branches.point_branch, branches.point_position


def _branch_of(self, node):
    """The branch a node belongs to (a junction to the branch that reaches it)."""
    if not 0 <= int(node) < len(self):
        raise ValueError(f"node {node} is not a node of the skeleton (it has {len(self)} nodes, numbered from 0).")
    return int(self.measure_branches().node_branch[int(node)])


Skeleton.measure_branches = _measure_branches
Skeleton.branches = property(_branches)
Skeleton.point_branches = property(_point_branches)
Skeleton.branch_of = _branch_of
Skeleton.to_networkx = _to_networkx
Skeleton.to_open3d = _to_open3d
Skeleton.__repr__ = _repr


from ._batch import skeletonize_files  # noqa: E402 (it calls skeletonize, defined above)
