// Bridging gaps in the data: a skeleton whose scan has a hole across a limb (an occluded
// stretch of a one-view scan, a missing patch) comes out in pieces, the limb stopping at
// the hole's edge on each side. Where a tip's limb points at another piece of the skeleton
// that lies close ahead of it, the two pieces are one part of the shape: a bone joins the
// tip to the nearest node of that piece inside the limb's cone. Pieces that lie side by
// side (two separate objects, two close parallel tubes) are not ahead of any tip and stay
// apart. The bones added are marked as inferred (SkeletonGraph::inferred). Not the paper's
// step; on by default (SkeletonGraphParameters::gapLimit says why).
#pragma once

#include "pcskeleton/skeleton/skeleton_graph.h"

#include <string>
#include <vector>

namespace pcskeleton {

struct GapBridgingReport {
    std::vector<Edge> bridges;         // the bones added, each from a tip to another piece
    std::vector<double> bridgeLengths;  // their lengths, in the skeleton's units
};

// "2 bridged, 0.126, 0.2 long" (or "none bridged")
std::string describe(const GapBridgingReport& report);

// Joins pieces of `skeleton` across gaps at most `gapLimit` node spacings long (the
// nearest first, one bone per pair of pieces); `nodeSpacing` is the thinning radius in the
// skeleton's units. gapLimit 0 bridges nothing.
GapBridgingReport bridgeGaps(SkeletonGraph& skeleton, double nodeSpacing, double gapLimit);

}  // namespace pcskeleton
