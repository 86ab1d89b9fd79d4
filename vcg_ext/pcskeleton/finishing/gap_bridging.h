// Bridging gaps in the data: a skeleton whose scan has a hole across a limb (an occluded
// stretch of a one-view scan, a missing patch) comes out in pieces, the limb stopping at
// the hole's edge on each side. Where a limb's end points at another piece of the skeleton
// that lies close ahead of it, the two pieces are one part of the shape: a bone joins the
// end to the nearest node of that piece inside the limb's cone. A limb ends at a tip, or at
// a corner where it turns into another limb (a plant's stem whose top is hidden behind a
// leaf, where the stem's piece turns into the leaf below). The gap is the empty space
// between them: from the end to the other piece's wall, not its axis (a thin limb hidden
// where it meets a thick body). A piece that thinned to a single node has no limb to look
// along and joins the nearest piece. Pieces that lie side by side (two separate objects,
// two close parallel tubes) are not ahead of any limb's end and stay apart. The bones added are
// marked as inferred (SkeletonGraph::inferred). Not the paper's step; on by default
// (SkeletonGraphParameters::gapLimit says why).
#pragma once

#include "pcskeleton/skeleton/skeleton_graph.h"

#include <string>
#include <vector>

namespace pcskeleton {

struct GapBridgingReport {
    std::vector<Edge> bridges;         // the bones added, each from a limb's end to another piece
    std::vector<double> bridgeLengths;  // their lengths, in the skeleton's units
};

// "2 bridged, 0.126, 0.2 long" (or "none bridged")
std::string describe(const GapBridgingReport& report);

// Joins pieces of `skeleton` across gaps at most `gapLimit` node spacings long (the
// nearest first, one bone per pair of pieces); `nodeSpacing` is the thinning radius in the
// skeleton's units. A gap is measured from a limb's end to the other piece's tube (the node's
// radius, `skeleton.radii`, taken off the distance to its axis); a node without a bone
// (a piece of data that thinned to one node) joins the nearest node of a piece whose tube
// is within the limit of its own, in any direction. gapLimit 0 bridges nothing.
GapBridgingReport bridgeGaps(SkeletonGraph& skeleton, double nodeSpacing, double gapLimit);

}  // namespace pcskeleton
