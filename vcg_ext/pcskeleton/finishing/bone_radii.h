// The radius of the tube around each bone, measured across the bone from the node's points.
//
// The embedding gives a node the mean distance of its points to it. Along a bone that
// overstates the tube: a node's points spread along the bone over a node spacing, and noise
// moves them along the bone and sideways, all of which adds to their distance. A bone
// node (two neighbours) is measured across its bone instead: the distance d of each point
// from the line through the node along the bone (from one neighbour to the other), and
//
//     r^2 = E[d^2] - 2 Var[d]
//
// For points on a circle of radius r with Gaussian noise of deviation s across the bone,
// E[d^2] = r^2 + 2 s^2 while Var[d] = s^2 to second order, so the noise cancels; a node off
// the tube's axis by e adds e^2 to E[d^2] and e^2 / 2 to Var[d], which cancels as well.
// Tips and junctions keep the embedding's radius: a tip's points wrap around its cap, and a
// junction holds the points of several arms. So do nodes whose points lie to one side of
// them, whose points are no noisy wall around the bone (all of them farther out than the
// radius measured), and nodes the new radius would leave away from their data (the
// invariant of data_support.h).
#pragma once

#include "pcskeleton/skeleton/skeleton_graph.h"

#include <vector>

namespace pcskeleton {

// Per node of `skeleton`: the radius of its bone measured from its points (`points` in
// skeleton.pointNode's order and the skeleton's frame), or 0 for a node left as it is (see
// above) or owning too few points to say. `nodeSpacing` in the same units.
std::vector<double> boneRadii(const SkeletonGraph& skeleton, const PointList& points, double nodeSpacing);

// Sets the radius of every node boneRadii measures, leaves the others.
void measureBoneRadii(SkeletonGraph& skeleton, const PointList& points, double nodeSpacing);

}  // namespace pcskeleton
