"""Curve skeletons of point clouds by Laplacian-based contraction.

After "Point Cloud Skeletons via Laplacian-Based Contraction" (Cao, Tagliasacchi, Olson,
Zhang, Su; SMI 2010), with the steps this project added for imperfect scans (outlier
detection, denoising, re-centring, refinement, tip extension, gap bridging) on by default
and ``paper=True`` for the paper's pipeline exactly. The same library as the ``pcskeleton``
command-line tool and the MeshLab plugins.

    >>> import pcskeleton
    >>> points = pcskeleton.read_points("scan.ply")            # (n, 3) float64
    >>> skeleton = pcskeleton.skeletonize(points)
    >>> skeleton.nodes, skeleton.edges, skeleton.radii          # (N, 3), (E, 2), (N,)
    >>> skeleton.correspondence                                # node per point, -1 for none
    >>> print(skeleton.report["text"])                         # cycles, tips, warnings
    >>> skeleton.write("scan_skeleton.ply")                    # also .obj, .cg
    >>> graph = skeleton.to_networkx()                         # needs networkx

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
    "SKELETON_PARAMETERS", "RECONSTRUCTION_PARAMETERS",
]

# The defaults, read from the library itself (the CLI's and the MeshLab dialog's too).
SKELETON_PARAMETERS = _pcskeleton.skeleton_defaults()
RECONSTRUCTION_PARAMETERS = _pcskeleton.reconstruction_defaults()

# What each keyword does and which way to turn it; the CLI option of the same name (with
# dashes) does the same. The defaults are filled in from the library.
_SKELETON_HELP = [
    ("paper", "the paper's pipeline exactly: no outlier detection, denoising, link limit, "
              "re-centring, refinement, gap bridging, tip extension or subsampling. Other "
              "keywords still apply on top (paper=True, refine=True is the paper plus refinement)."),
    ("k", "neighbours whose tangent-plane Delaunay triangulation gives each point's 1-ring; "
          "0 = 1.2% of the points, between 8 and 30. Raise for noisy scans; lower if close "
          "parts get connected."),
    ("wl", "initial contraction weight W_L0; 0 = 1/(5 x mean 1-ring size). Too high pulls thin "
           "parts into thick ones; too low leaves tips sticking out."),
    ("wh", "initial attraction weight W_H0; opposes wl."),
    ("sl", "W_L grows by this factor per iteration; 2 when thin parts join thick ones (paper Fig. 10)."),
    ("max_wl", "cap on W_L."),
    ("max_wh", "cap on each point's W_H."),
    ("row_limit", "cap on a Laplacian row's weight sum."),
    ("iterations", "contraction iterations at most; raise if the report says the limit was reached."),
    ("threshold", "stop when the 1-ring size shrinks by less than this fraction in an iteration."),
    ("radius", "thinning ball radius, a fraction of the bounding-box diagonal. Larger merges "
               "close parts and small loops; smaller keeps more detail and more noise."),
    ("link_limit", "1-ring neighbours whose contracted points ended more than this many radii "
                   "apart connect their nodes only where nothing else does. Lower it if close "
                   "parts get false loops; 0 = every neighbour connects (the paper)."),
    ("gap_limit", "a limb pointing at another piece of the skeleton at most this many radii "
                  "ahead (a gap in the data) is joined to it; 0 = no bridge (the paper)."),
    ("extend_tips", "extend each limb to the end of its tip's points (contraction shortens limbs)."),
    ("refine", "remove short spurs and loops smaller than their tube, merge junctions closer "
               "than the node spacing, open loops narrower than their tube where parts touch "
               "(noise and misaligned scans leave them)."),
    ("loop_opening", "refinement opens a loop whose hole is narrower than this many tube radii at "
                     "its bone longest for its radii, if that bone passes closer than "
                     "loop_clearance of its radius to a point (parts that touch); 0 opens none."),
    ("loop_clearance", "see loop_opening; lower either if a real narrow hole is lost."),
    ("gap_stretch", "refinement cuts a bone that joins two strands straight across the gap between "
                    "them (on a loop, between junctions the strands run through) when it is longer "
                    "than this many times the radii at its two ends together; 0 cuts none."),
    ("recentre", "move a node whose points cover one side of its bone only (one-view scans, "
                 "holes) to the centre of the circle through them."),
    ("keep_outliers", "contract every point; by default points that do not belong to the sampled "
                      "surface get no node (-1 in correspondence)."),
    ("outlier_isolation", "a point whose 8th nearest neighbour is farther than this many typical "
                          "spacings is an outlier; raise it if sparse parts are taken for outliers."),
    ("outlier_local", "a point whose 8th nearest neighbour is farther than this times that of its "
                      "neighbours is an outlier; lower finds outliers closer to the surface."),
    ("outlier_cluster", "groups holding less than this share of the cloud are outlier clusters; 0 keeps every group."),
    ("denoise", "contract a copy denoised by this many passes of projection onto local planes; "
                "-1 = automatic (only noisy clouds), 0 = never."),
    ("contracted_points", "clouds with more points are contracted through a well-spread subsample "
                          "of at most this many; every point still gets its node. Up to 20000 the "
                          "skeleton is the same on every CPU; above, a faster solver's may differ."),
    ("full_resolution", "contract every point (the paper's way; about 2.7 KB per point)."),
    ("memory_limit", "refuse, before any work, a run needing more than this many GB; None = 80% of the machine."),
]
_RECONSTRUCTION_HELP = [
    ("paper", "the paper's plain fit with uniform point weights and the zero level set as it is."),
    ("resolution", "grid cells along the longest side of the domain (16-512)."),
    ("smooth_weight", "w1, smoothness of the field."),
    ("surface_weight", "w2, the surface passes through the points."),
    ("skeleton_weight", "w3, the field is -radius on the skeleton."),
    ("outside_weight", "w4, the field is positive far from the skeleton."),
    ("outside_radii", "'far' is more than this many node radii from the skeleton."),
    ("data_topology", "the paper's plain fit: the surface may have handles and parts the skeleton "
                      "has not (by default it has exactly the skeleton's topology)."),
    ("uniform_point_weights", "every point weighs w2 (the paper); by default noisy points weigh less."),
    ("level_set", "the field's zero level set as it is (the paper); by default, where there are points, "
                  "the surface's vertices move (at most a grid cell) onto a local fit of the points."),
]


def _describe(table, defaults):
    return "\n".join(textwrap.fill(f"{name} [{defaults[name]!r}]: {text}", width=88, initial_indent="    ",
                                   subsequent_indent="        ") for name, text in table)


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
    parameters: keywords, each as the CLI's option of the same name [default]:

{_describe(_SKELETON_HELP, SKELETON_PARAMETERS)}

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


def skeleton_from_contraction(contraction, *, progress=None):
    """Thinning and embedding (paper steps 4-5) of a Contraction's current state, then the
    steps after them, with the keywords the Contraction was given. Every input point gets
    its node, also through a subsample."""
    return contraction._skeleton(progress)


def reconstruct(points, skeleton, *, progress=None, **parameters):
    return _pcskeleton._reconstruct(_points_of(points), skeleton, parameters, progress)


reconstruct.__doc__ = f"""A closed surface through the points whose inside and topology follow the
    skeleton (paper Sec. V): one component per skeleton component, genus = its cycles.

    points: the scan the skeleton belongs to, (n, 3) or an Open3D PointCloud.
    skeleton: a Skeleton with radii (skeletonize's, read_skeleton's of a .ply, or edited).
    parameters [default]:

{_describe(_RECONSTRUCTION_HELP, RECONSTRUCTION_PARAMETERS)}

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


Skeleton.to_networkx = _to_networkx
Skeleton.to_open3d = _to_open3d
Skeleton.__repr__ = _repr
