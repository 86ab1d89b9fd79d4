// Close-by parts: a point's k nearest can include points of another part whose wall faces
// its own across a narrow gap (an arm hanging beside a body, two legs side by side). A
// 1-ring across that gap ties the two parts together, and contraction pulls them into one
// (the paper's stated limitation, Sec. VI). Such a neighbour is told from the far side of
// the point's own thin tube, which lies as steeply off the tangent plane, by the side it
// lies on: the other wall lies outside the point's surface, and faces it; the own far side
// lies inside. Outside is read from each point's own surface curvature, where that is clear.
#pragma once

#include "pcskeleton/core/point.h"

namespace pcskeleton {

class PointIndex;

// Per point, the unit normal of its surface pointing out of the shape, from the curvature
// of a quadric fitted to its nearest points: a convex surface bends away from outside.
// Zero where the curvature does not say which side is out (flat, a saddle, or a rise across
// the neighbourhood buried in the fit's residual, as on noisy scans).
PointList outwardNormals(const PointList& points, const PointIndex& index);

// Whether q lies on a wall facing p's across a gap: each lies outside the other's surface
// and their normals face each other. False when either normal is zero.
bool onFacingWall(const Point& p, const Point& pOut, const Point& q, const Point& qOut);

}  // namespace pcskeleton
