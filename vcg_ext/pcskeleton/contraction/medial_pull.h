// Not in the paper: a pull of each point towards its own estimate of the medial axis.
//
// Laplacian contraction moves a point along its surface's mean-curvature normal. Where a
// ring's hole is narrow next to its tube, the inner wall curves more around the hole than
// across the tube, so it moves into the hole, the ring flattens into a disc and its loop is
// lost (the paper: "high contraction forces can also collapse branches around a small
// tunnel"). Mean-curvature skeletons hold such walls with a pull towards medial points;
// this is the same pull for a point cloud. Each point's medial point is the centre of the
// largest empty ball that touches it on its inner side (a shrinking ball), with the inner
// side from normals oriented consistently over the whole cloud. The contraction then adds
// W_M² |p' - m|² to each point's terms (laplacian_contraction.h).
#pragma once

#include "pcskeleton/core/point.h"

#include <cstddef>
#include <vector>

namespace pcskeleton {

struct MedialTargets {
    PointList centres;        // one per point: its medial ball's centre, or the point itself
    std::vector<char> found;  // whether the point has a medial centre to be pulled to
    std::size_t count = 0;    // points with one

    bool empty() const { return count == 0; }
};

// For each point, the centre of the largest ball empty of points that touches it on the
// side its oriented normal points away from. A point has none where its normal could not
// be oriented (a part its neighbours do not reach) or where the ball never closes within
// the cloud's size (the open side of a scan seen from one direction, a lone sheet).
MedialTargets estimateMedialTargets(const PointList& points);

}  // namespace pcskeleton
