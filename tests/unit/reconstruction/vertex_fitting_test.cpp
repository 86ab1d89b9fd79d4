// The fine pass of the reconstruction: where there are points, the surface's vertices come
// onto them; where there are none, nothing moves; the topology never changes.
#include "support/sampled_shapes.h"
#include <pcskeleton/reconstruction/skeleton_reconstruction.h>
#include <pcskeleton/reconstruction/vertex_fitting.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace pcskeleton;

namespace {


const shapes::Polyline kAxis = {{Point(0, 0, 0), Point(0, 0, 2)}};

}  // namespace

TEST(VertexFitting, AThinTubesSurfaceComesOntoItsWall) {
    // A tube a few cells thick: the field's smoothness rounds its wall inward.
    const PointList scan = shapes::tube(kAxis, 0.1, 8000, 3);
    const SkeletonGraph skeleton = shapes::curveSkeleton(kAxis, 0.1);
    ReconstructionParameters parameters;
    parameters.resolution = 96;
    const Reconstruction fitted = reconstructFromSkeleton(scan, skeleton, parameters);
    parameters.fitVerticesToPoints = false;
    const Reconstruction levelSet = reconstructFromSkeleton(scan, skeleton, parameters);

    EXPECT_GT(fitted.report.vertexFitting.moved, fitted.mesh.vertices.size() / 2);
    EXPECT_FALSE(levelSet.report.verticesFitted);
    EXPECT_EQ(fitted.mesh.triangles, levelSet.mesh.triangles) << "only the vertices move";
    EXPECT_EQ(fitted.report.topology.genus, 0);
    EXPECT_EQ(fitted.report.topology.components, 1);
    EXPECT_TRUE(fitted.report.topology.closedManifold());
    const double fittedDistance = shapes::meanDistanceToCylinderWall(fitted.mesh.vertices, 0.1, 0.3, 1.7);
    const double levelSetDistance = shapes::meanDistanceToCylinderWall(levelSet.mesh.vertices, 0.1, 0.3, 1.7);
    std::printf("mean distance to the wall: %.5f fitted, %.5f level set (cell %.4f)\n", fittedDistance,
                levelSetDistance, fitted.report.cellSize);
    EXPECT_LT(fittedDistance, 0.3 * levelSetDistance);
    EXPECT_LT(fittedDistance, 0.05 * fitted.report.cellSize);
}

TEST(VertexFitting, NothingMovesWhereThereAreNoPoints) {
    const PointList scan = shapes::tube(kAxis, 0.1, 4000, 5);
    ReconstructionParameters parameters;
    parameters.resolution = 48;
    parameters.fitVerticesToPoints = false;
    const Reconstruction surface = reconstructFromSkeleton(scan, shapes::curveSkeleton(kAxis, 0.1), parameters);
    PointList farAway = scan;
    for (Point& p : farAway) p.x() += 1.0;  // many cells beside the surface
    TriangleMesh mesh = surface.mesh;
    const VertexFittingReport report = fitVerticesToPoints(mesh, farAway, surface.report.cellSize);
    EXPECT_EQ(report.moved, 0u);
    EXPECT_EQ(mesh.vertices, surface.mesh.vertices);
}
