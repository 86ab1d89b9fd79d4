#include "screen_projection.h"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <limits>

namespace pcskeleton::edit {

ScreenProjection ScreenProjection::fromGl(const double modelView[16], const double projection[16],
                                          const int viewport[4]) {
    ScreenProjection view;
    view.modelViewProjection = Eigen::Map<const Eigen::Matrix4d>(projection) * Eigen::Map<const Eigen::Matrix4d>(modelView);
    view.viewport = Eigen::Vector4d(viewport[0], viewport[1], viewport[2], viewport[3]);
    view.valid = true;
    return view;
}

Eigen::Vector3d ScreenProjection::toScreen(const Point& p) const {
    const Eigen::Vector4d clip = modelViewProjection * p.homogeneous();
    const Eigen::Vector3d ndc = clip.head<3>() / clip.w();
    return {viewport[0] + (ndc.x() + 1.0) * 0.5 * viewport[2], viewport[1] + (ndc.y() + 1.0) * 0.5 * viewport[3],
            (ndc.z() + 1.0) * 0.5};
}

Point ScreenProjection::toWorld(const Eigen::Vector3d& screen) const {
    const Eigen::Vector4d ndc((screen.x() - viewport[0]) / viewport[2] * 2.0 - 1.0,
                              (screen.y() - viewport[1]) / viewport[3] * 2.0 - 1.0, screen.z() * 2.0 - 1.0, 1.0);
    const Eigen::Vector4d world = modelViewProjection.inverse() * ndc;
    return world.head<3>() / world.w();
}

int nodeAt(const ScreenProjection& view, const PointList& nodes, const Eigen::Vector2d& at, double maxPixels) {
    int best = -1;
    double bestDistance = maxPixels, bestDepth = std::numeric_limits<double>::infinity();
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        const Eigen::Vector3d s = view.toScreen(nodes[n]);
        const double distance = (s.head<2>() - at).norm();
        // Within a pixel of each other, the node in front wins.
        const bool closer = distance < bestDistance - 1.0 || (distance <= bestDistance + 1.0 && s.z() < bestDepth);
        if (distance <= maxPixels && closer) {
            best = static_cast<int>(n);
            bestDistance = distance;
            bestDepth = s.z();
        }
    }
    return best;
}

std::vector<int> nodesInRectangle(const ScreenProjection& view, const PointList& nodes, const Eigen::Vector2d& cornerA,
                                  const Eigen::Vector2d& cornerB) {
    const Eigen::Vector2d low = cornerA.cwiseMin(cornerB), high = cornerA.cwiseMax(cornerB);
    std::vector<int> inside;
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        const Eigen::Vector2d s = view.toScreen(nodes[n]).head<2>();
        if ((s.array() >= low.array()).all() && (s.array() <= high.array()).all()) inside.push_back(static_cast<int>(n));
    }
    return inside;
}

Point screenParallelOffset(const ScreenProjection& view, const Point& anchor, const Eigen::Vector2d& from,
                           const Eigen::Vector2d& to) {
    const double depth = view.toScreen(anchor).z();
    return view.toWorld({to.x(), to.y(), depth}) - view.toWorld({from.x(), from.y(), depth});
}

}  // namespace pcskeleton::edit
