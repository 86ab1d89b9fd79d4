// Tip extension (after the paper's step 5). Contraction pulls the ends of limbs inwards,
// so the tip node, the centre of its points, stops short of the limb's end: the skeleton
// is shorter than the shape. Each limb that is not a spur is extended from its tip, along
// its direction over the last bones, to the farthest of the tip's own points that lie
// within 1.5 tip radii of the limb's axis (outliers and noise off to the side do not
// count).
//
// The new end node owns no points (the tip keeps them); its radius is the thickness of
// the shape at the end: the mean distance from the limb's axis of the tip's points in the
// last quarter-radius before the end.
#pragma once

#include "pcskeleton/skeleton/skeleton_graph.h"

namespace pcskeleton {

struct TipExtensionReport {
    int extendedTips = 0;
    double meanLength = 0.0, longest = 0.0;  // of the added bones, input units
};

// `points` are the input points (skeleton.pointNode's frame and order); `nodeSpacing` is
// the thinning radius in input units. Limbs are extended when they would grow by more
// than a tenth of the node spacing.
TipExtensionReport extendTips(SkeletonGraph& skeleton, const PointList& points, double nodeSpacing);

}  // namespace pcskeleton
