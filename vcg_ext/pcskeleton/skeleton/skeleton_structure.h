// The parts of a skeleton graph that its quality checks, refinement and tip extension
// reason about: limbs (tip-to-junction branches), spurs, short cycles and close junctions.
//
// Criteria are geometric and relative to the skeleton itself, so they hold in any unit:
// - a spur is a limb shorter than the radius at its junction (its tip is inside the body
//   it sprouts from) or than the node spacing;
// - a limb is redundant when the rest of the skeleton already accounts for its points:
//   nearly all of them lie in the tube (radius plus node spacing; across a flat strip, out
//   to the strip's edge) of a node off the limb. Noise, gaps and one-sided scans sprout
//   such limbs from the side of a bone, and a leaf's or plate's rim from its mid-line; a
//   real limb, however short, has points beyond the body it leaves;
// - a corner limb is a short limb out of the outer corner of a bend, as thick as the tube
//   that bends and reaching no farther than its corner;
// - a cycle is spurious when its hole is not there: the cycle's nodes lie closer to their
//   centre than the tube around them is thick, or than the node spacing;
// - two junctions are close when the bone path between them is shorter than the node
//   spacing.
#pragma once

#include "pcskeleton/skeleton/skeleton_graph.h"

#include <vector>

namespace pcskeleton {

// Walks from `from` into `next` and on through nodes of degree 2; returns the nodes passed,
// `from` first, ending at the first node whose degree is not 2 (or back at `from` on a
// cycle without junctions). `neighbours` as adjacencyLists gives them.
std::vector<int> walkChain(const std::vector<std::vector<int>>& neighbours, int from, int next);

// Total length of the bones along a node path.
double pathLength(const SkeletonGraph& graph, const std::vector<int>& path);

// The unit direction from a chain's first node (walkChain's `from`) to its node `bones`
// bones along, or to its last node when it is shorter; zero when the two coincide. Over
// several bones, as one bone zig-zags with the nodes' placement.
Point chainDirection(const SkeletonGraph& graph, const std::vector<int>& chain, std::size_t bones);

// From a tip along nodes of degree 2 to the first node of another degree (a junction, or
// the other tip of an isolated chain), both ends included.
struct Limb {
    std::vector<int> path;    // path.front() is the tip, path.back() where the limb ends
    double length = 0.0;
    bool atJunction = false;  // false for an isolated chain, which ends at another tip
};

std::vector<Limb> tipLimbs(const SkeletonGraph& graph);

bool isSpur(const SkeletonGraph& graph, const Limb& limb, double nodeSpacing);

// The straggling ends of the limbs. Noise scatters a few points past a limb's end, and
// thinning can string them into small nodes that bend the end sideways (a hook, which
// sends tip extension off the axis) or sprout a limb of their own. A straggling end is
// the nodes from a tip that each own fewer than a tenth of the points of the skeleton's
// median node, up to (and with, last) the first node that owns more, if they all lie
// within that node's radius plus two node spacings of it. That node may be the junction
// the limb ends at (the whole limb is stragglers) only if the limb's nodes together own
// fewer points than that tenth: a thin limb has few points per node, but more in all.
// A limb whose tip owns more has a straggling end when it is hooked: from the tip up to a
// node where the limb turns more than 60 degrees (bone against bone), all within that
// node's radius plus a node spacing of it and owning fewer points together than it (noise
// gathered at the side of a limb's end).
std::vector<std::vector<int>> stragglingEnds(const SkeletonGraph& graph,
                                             const std::vector<std::vector<int>>& nodePoints, double nodeSpacing);

// Stray bridges: paths between two junctions whose inner nodes together own fewer than a
// tenth of the points of the skeleton's median node (the share stragglingEnds uses), and
// that lie on a loop or join two parts side by side (at both ends the path leaves a
// junction of three or four bones from the side, two of the others meeting at more than
// 120 degrees, straighter than a symmetric Y); and U-turns: runs of nodes in a chain, owning as few
// points in all, from whose two ends the chain runs on the same way (within 60 degrees),
// two parts side by side joined at their ends.
// Where two parts pass close by (the strands of a knot at a crossing, two parallel tubes
// under noise, scans misaligned across a gap), contraction pulls the few points of their
// facing walls into the gap, and thinning strings them into a node or two that joins the
// parts: a false loop, or one part where there are two. A real handle or connection,
// however thin, has more points than that. Each path is given from end to end (junction
// to junction, or the two nodes beside a U-turn); a path without inner nodes is not judged
// (see bonesAcrossGaps).
std::vector<std::vector<int>> strayBridges(const SkeletonGraph& graph, const std::vector<std::vector<int>>& nodePoints);

// Bones across gaps: a bone joining two junctions directly, each a junction of three or four
// bones two of whose others meet at more than 120 degrees, on a loop, and longer than `minStretch`
// (RefinementLimits::gapStretch; 0 = none) times the two radii at its ends together, so
// that the tubes of the strands it joins do not meet along it. Where two strands pass
// close, thinning can join them by one such bone across the gap between them: a false
// loop. Bones between tubes thinner than the node spacing are not judged (any bone between
// neighbouring junctions is longer than their radii there). Most stretched first.
std::vector<Edge> bonesAcrossGaps(const SkeletonGraph& graph, double nodeSpacing, double minStretch);

// `points` are the skeleton's input points (graph.pointNode's), `nodePoints` their lists
// per node (pointsOfNodes); false for a limb without points or not at a junction.
bool isRedundantLimb(const SkeletonGraph& graph, const Limb& limb, const PointList& points,
                     const std::vector<std::vector<int>>& nodePoints, double nodeSpacing);

// A corner limb: where a tube turns a corner, contraction can draw the bend's outer wall
// into a short limb pointing out of it, longer than the radius (no spur) and with points
// outside the other nodes' tubes (not redundant). A limb is one when the junction's two
// other bones bend (meet at 135 degrees or less), the limb leaves into the outer corner
// (within 60 degrees of the direction away from both), it is about as thick as the thinner
// of them (a real limb off a thick body is thinner than the body), and its points reach no
// farther from the junction than a mitred bend of that thinner tube would, with slack for
// noise and for the junction lying inside the bend. Same arguments as isRedundantLimb.
bool isCornerLimb(const SkeletonGraph& graph, const Limb& limb, const PointList& points,
                  const std::vector<std::vector<int>>& nodePoints);

// One short cycle per independent cycle: for every bone outside a spanning forest, the
// bone plus the shortest path (by length) between its ends that avoids it.
std::vector<std::vector<int>> shortCycleBasis(const SkeletonGraph& graph);

bool isSpuriousCycle(const SkeletonGraph& graph, const std::vector<int>& cycle, double nodeSpacing);

// A loop whose opening (the mean distance of its nodes from their centroid, less their
// mean radius) is narrower than `minOpening` tube radii: parts that touch, or that noise
// joined across a narrow gap, rather than a hole the shape has.
bool isNarrowCycle(const SkeletonGraph& graph, const std::vector<int>& cycle, double minOpening);

// Bones over gaps in the data: a bone on a loop, from a junction to a node of a chain (two
// bones), longer than `minStretch` (RefinementLimits::gapStretch; 0 = none) times the radii
// at its two ends together, whose two nodes' points come no nearer to each other than
// kDataGapSpacings times the spacing of those points (the median distance from one of them
// to its nearest). The end of a limb beside another part (an arm by the body, a finger by
// the palm) seen from one side: contraction draws the two together and thinning joins them
// across space where the data has no points, a false loop. Along a real bone the two nodes'
// points meet; a loop that runs on across an occluded stretch does so between chain nodes,
// not from a junction. Widest gap (in spacings) first.
inline constexpr double kDataGapSpacings = 4.0;
std::vector<Edge> bonesOverDataGaps(const SkeletonGraph& graph, const PointList& points,
                                    const std::vector<std::vector<int>>& nodePoints, double minStretch);

// The bone of `cycle` (consecutive nodes, closing back to the first) longest for its
// nodes' radii: where the loop crosses from one part to another, their balls do not meet.
Edge mostStretchedBone(const SkeletonGraph& graph, const std::vector<int>& cycle);

// Whether the middle of `bone` passes closer to the surface than `minClearance` of its
// radius: a bone inside a tube keeps about a radius from its wall, one across a contact
// between two parts passes through their surfaces.
bool boneGrazesSurface(const SkeletonGraph& graph, const Edge& bone, const PointList& points,
                       const std::vector<std::vector<int>>& nodePoints, double minClearance);

// When a loop is a contact between parts rather than a hole: its opening is under
// minOpening tube radii, or a bone passes within minClearance of its radius of a point.
// A bone across a gap (bonesAcrossGaps) is longer than gapStretch times the radii at its
// two ends together; 0 = none is cut. Defaults chosen with bench_robustness
// --loop-opening, --loop-clearance and --gap-stretch (docs/benchmarks.md#measurements-behind-the-constants).
struct RefinementLimits {
    double minOpening = 1.0;     // in tube radii; 0 = no loop is a contact
    double minClearance = 0.35;  // fraction of the bone's radius
    double gapStretch = 1.15;    // times the two end radii; 0 = no bone crosses a gap
    double minHole = 1.0;        // node spacings, the radius of a loop's empty disc; 0 = none is filled
};

// A loop without a hole (a contact, or a loop over data) and the bone refinement opens it at.
struct LoopToOpen {
    std::vector<int> cycle;  // consecutive nodes, as shortCycleBasis gives them
    Edge bone;               // its most stretched bone (for a contact, the one that grazes the surface)
};

// The loops of shortCycleBasis that are narrow (isNarrowCycle) and whose most stretched
// bone grazes the surface (boneGrazesSurface); `points` are the skeleton's input points.
std::vector<LoopToOpen> contactLoops(const SkeletonGraph& graph, const PointList& points,
                                      const RefinementLimits& limits);

// The radius of the widest disc inside a loop that none of its own points covers: the loop's
// nodes and their points projected on the nodes' best-fit plane, the disc centred inside the
// projected loop. Around a hole the shape has, the points lie on the tube that goes round it
// and leave a disc as wide as the hole; where the loop's points cover its inside (a one-view
// scan of a dome contracts to a ring along its rim; a limb touching the body) only the gaps
// between samples are left. Only its own points: other parts of the shape may lie in front
// of a real hole, seen along the loop's axis. Disc centres are tried `step` apart (at most
// 150 along the loop's extent): the radius found is within step / sqrt(2) of the widest.
double emptyDiscRadius(const SkeletonGraph& graph, const std::vector<int>& cycle, const PointList& points,
                       const std::vector<std::vector<int>>& nodePoints, double step);

// Whether a limb of the skeleton lies across a loop's hole: two or more nodes of the loop's
// own connected part, on no loop (of shortCycleBasis), inside the loop's nodes projected on
// their best-fit plane and farther from that plane than the loop's mean radius. Around a hole the
// shape has, nothing lies there (seen along the loop's axis, one sees through it); from one
// view, a limb or a finger in front of a body hides the body behind it, and contraction rings
// that shadow as if it were a hole. Nodes of other loops do not count: a knot's strands cross
// over each other's loops.
bool partAcrossLoop(const SkeletonGraph& graph, const std::vector<int>& cycle);

// The loops of shortCycleBasis that the data does not show as holes, each with its most
// stretched bone: their empty disc is narrower than `limits.minHole` node spacings (loops the
// data fills), or a limb lies across them (partAcrossLoop). None when
// `limits.minHole` is 0.
std::vector<LoopToOpen> filledLoops(const SkeletonGraph& graph, const PointList& points, double nodeSpacing,
                                     const RefinementLimits& limits);

// Paths (through degree-2 nodes) that join two junctions and are shorter than `nodeSpacing`.
std::vector<std::vector<int>> closeJunctionPaths(const SkeletonGraph& graph, double nodeSpacing);

}  // namespace pcskeleton
