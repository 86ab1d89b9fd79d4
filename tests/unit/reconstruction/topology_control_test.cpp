#include "support/grid_fields.h"
#include <pcskeleton/reconstruction/iso_surface.h>
#include <pcskeleton/reconstruction/topology_control.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <utility>

using namespace pcskeleton;

namespace {

constexpr double kPi = 3.14159265358979323846;

FieldGrid cube(int cells) { return shapes::cubeGrid(cells, 1.6); }

std::vector<double> sample(const FieldGrid& grid, const std::function<double(const Point&)>& distance) {
    return shapes::sampleField(grid, distance);
}

double torus(const Point& p) { return std::hypot(std::hypot(p.x(), p.y()) - 1.0, p.z()) - 0.3; }

// The torus's centre circle with `nodes` nodes; `closed` joins the last to the first.
SkeletonGraph ring(int nodes, bool closed) {
    SkeletonGraph g;
    for (int n = 0; n < nodes; ++n) {
        const double a = 2 * kPi * n / nodes;
        g.nodes.push_back(Point(std::cos(a), std::sin(a), 0));
        g.radii.push_back(0.3);
        if (n > 0) g.edges.push_back({n - 1, n});
    }
    if (closed) g.edges.push_back({nodes - 1, 0});
    return g;
}

}  // namespace

TEST(TopologyControl, ABallGrownFromItsCentreKeepsEveryInsideNode) {
    const FieldGrid grid = cube(40);
    std::vector<double> values = sample(grid, [](const Point& p) { return p.norm() - 1.0; });
    SkeletonGraph centre;
    centre.nodes = {Point::Zero()};
    centre.radii = {1.0};
    const TopologyControl control = constrainToSkeletonTopology(grid, centre, values);
    EXPECT_GT(control.insideNodes, 1000u);
    EXPECT_EQ(control.removedNodes, 0u);
    const SurfaceTopology t = analyseSurface(extractZeroLevelSet(grid, values));
    EXPECT_EQ(t.components, 1);
    EXPECT_EQ(t.genus, 0);
}

namespace {

// The exact torus's field controlled by its ring, closed or cut, and the surface it gives.
std::pair<TopologyControl, SurfaceTopology> torusControlledBy(const SkeletonGraph& skeleton) {
    const FieldGrid grid = cube(48);
    std::vector<double> values = sample(grid, torus);
    const TopologyControl control = constrainToSkeletonTopology(grid, skeleton, values);
    return {control, analyseSurface(extractZeroLevelSet(grid, values))};
}

}  // namespace

TEST(TopologyControl, ATorusWithItsRingKeepsItsHandle) {
    const auto [control, t] = torusControlledBy(ring(12, true));
    EXPECT_EQ(control.removedNodes, 0u);
    EXPECT_TRUE(t.closedManifold());
    EXPECT_EQ(t.components, 1);
    EXPECT_EQ(t.genus, 1);
}

TEST(TopologyControl, ATorusWithACutRingLosesItsHandleAndLittleElse) {
    const auto [control, t] = torusControlledBy(ring(12, false));
    EXPECT_TRUE(t.closedManifold());
    EXPECT_EQ(t.components, 1);
    EXPECT_EQ(t.genus, 0);
    // The cut is one slice across the tube, not the tube.
    EXPECT_GT(control.removedNodes, 0u);
    EXPECT_LT(control.removedNodes * 20, control.insideNodes);
}

TEST(TopologyControl, AnIslandAwayFromTheSkeletonIsRemoved) {
    const FieldGrid grid = cube(40);
    std::vector<double> values = sample(grid, [](const Point& p) {
        return std::min((p - Point(-0.8, 0, 0)).norm() - 0.5, (p - Point(0.8, 0, 0)).norm() - 0.5);
    });
    SkeletonGraph left;
    left.nodes = {Point(-0.8, 0, 0)};
    left.radii = {0.5};
    const TopologyControl control = constrainToSkeletonTopology(grid, left, values);
    EXPECT_NEAR(double(control.removedNodes), control.insideNodes / 2.0, control.insideNodes * 0.02);
    EXPECT_NEAR(control.largestRemovalCentre.x(), 0.8, grid.spacing);
    const SurfaceTopology t = analyseSurface(extractZeroLevelSet(grid, values));
    EXPECT_EQ(t.components, 1);
    EXPECT_EQ(t.genus, 0);
}
