// Where skeleton nodes appear on screen, from the OpenGL matrices captured while drawing:
// picking a node under the mouse, rubber-band selection, and dragging nodes parallel to
// the screen. No OpenGL calls here, so it is tested without a window.
#pragma once

#include <pcskeleton/contraction/point_cloud_input.h>

#include <Eigen/Core>

#include <vector>

namespace pcskeleton::edit {

struct ScreenProjection {
    Eigen::Matrix4d modelViewProjection = Eigen::Matrix4d::Identity();  // projection * model-view
    Eigen::Vector4d viewport{0, 0, 1, 1};                               // x, y, width, height (device pixels)
    bool valid = false;                                                 // false until something was drawn

    // Column-major arrays, as glGetDoublev and glGetIntegerv give them.
    static ScreenProjection fromGl(const double modelView[16], const double projection[16], const int viewport[4]);

    // Window x, y (device pixels, y up as in OpenGL) and depth in [0, 1].
    Eigen::Vector3d toScreen(const Point& p) const;
    Point toWorld(const Eigen::Vector3d& screen) const;
};

// The node drawn nearest to `at` within `maxPixels`, the front one among equals; -1 if none.
int nodeAt(const ScreenProjection& view, const PointList& nodes, const Eigen::Vector2d& at, double maxPixels);

// The nodes whose screen position lies in the rectangle spanned by two corners.
std::vector<int> nodesInRectangle(const ScreenProjection& view, const PointList& nodes, const Eigen::Vector2d& cornerA,
                                  const Eigen::Vector2d& cornerB);

// The displacement, parallel to the screen at the depth of `anchor`, that follows the
// mouse from `from` to `to` (window pixels).
Point screenParallelOffset(const ScreenProjection& view, const Point& anchor, const Eigen::Vector2d& from,
                           const Eigen::Vector2d& to);

}  // namespace pcskeleton::edit
