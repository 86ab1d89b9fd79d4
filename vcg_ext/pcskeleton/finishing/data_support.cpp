#include "pcskeleton/finishing/data_support.h"

#include "pcskeleton/internal/spatial_index.h"

#include <limits>

namespace pcskeleton {

DataSupport::DataSupport(const PointList& points, double nodeSpacing)
    : points_(points), slack_(kSupportSlack * nodeSpacing), box_(boundingBox(points)),
      // CGAL's k-d tree must not be built on no points; with none, nothing is supported.
      index_(points.empty() ? nullptr : std::make_unique<PointIndex>(points)) {
    box_.min().array() -= slack_;
    box_.max().array() += slack_;
}

DataSupport::~DataSupport() = default;

bool DataSupport::supports(const Point& position, double radius, const std::vector<int>& ownPoints) const {
    if (!position.allFinite() || !box_.contains(position)) return false;
    double nearest = std::numeric_limits<double>::infinity();
    if (ownPoints.empty()) {
        if (!index_) return false;
        std::vector<int> found;
        index_->nearest(position, 1, found);
        if (!found.empty()) nearest = (points_[found[0]] - position).norm();
    } else {
        for (int i : ownPoints) nearest = std::min(nearest, (points_[i] - position).norm());
    }
    return nearest <= std::max(radius, 0.0) + slack_;
}

std::vector<int> DataSupport::unsupportedNodes(const SkeletonGraph& skeleton) const {
    const std::vector<std::vector<int>> members = pointsOfNodes(skeleton);
    std::vector<int> away;
    for (std::size_t n = 0; n < skeleton.nodeCount(); ++n) {
        if (!supports(skeleton.nodes[n], skeleton.radii[n], members[n])) away.push_back(int(n));
    }
    return away;
}

}  // namespace pcskeleton
