// Tip extension (after the paper's step 5). Contraction pulls the ends of limbs inwards,
// so the tip node, the centre of its points, stops short of the limb's end: the skeleton
// is shorter than the shape. Each limb that is not a spur is extended from its tip, along
// its direction over the last bones, to where its points end: those of the tip and of the
// nodes behind it up to two node spacings and the tip's diameter away (the stretch that
// sets the direction) that lie within 1.5 radii of the limb's axis
// (outliers and noise off to the side do not count), and where their density along the
// axis falls to half its level (on a clean limb the farthest of them; under noise, not
// the noise's tail beyond the end).
//
// The new end node owns no points (the tip keeps them); its radius is the thickness of
// the shape at the end: the mean distance from the limb's axis of those points in the last
// quarter of the tip's radius before the end.
#pragma once

#include "pcskeleton/finishing/data_support.h"
#include "pcskeleton/skeleton/skeleton_graph.h"

namespace pcskeleton {

struct TipExtensionReport {
    int extendedTips = 0;
    double meanLength = 0.0, longest = 0.0;  // of the added bones, input units
    int refused = 0;  // extensions whose end would have left the data (data_support.h)
};

// `points` are the input points (skeleton.pointNode's frame and order); `nodeSpacing` is
// the thinning radius in input units. Limbs are extended when they would grow by more
// than a tenth of the node spacing, and only when the new end stays with the data
// (`support`, made on the same points).
TipExtensionReport extendTips(SkeletonGraph& skeleton, const PointList& points, double nodeSpacing,
                              const DataSupport& support);

}  // namespace pcskeleton
