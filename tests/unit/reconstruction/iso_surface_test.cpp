// The zero level set of a grid field and its topology: closed surfaces of known genus from
// analytic fields, and the topology numbers on meshes built by hand.
#include "support/grid_fields.h"
#include <pcskeleton/core/errors.h>
#include <pcskeleton/reconstruction/iso_surface.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace pcskeleton {
namespace {

FieldGrid cube(int cells) { return shapes::cubeGrid(cells, 1.2); }

std::vector<double> sample(const FieldGrid& grid, const std::function<double(const Point&)>& field) {
    return shapes::sampleField(grid, field);
}

double signedVolume(const TriangleMesh& mesh) {
    double volume = 0;
    for (const auto& t : mesh.triangles)
        volume += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]])) / 6.0;
    return volume;
}

TEST(IsoSurface, SphereFieldGivesAClosedSphereThroughTheZeroSet) {
    const FieldGrid grid = cube(32);
    const TriangleMesh mesh = extractZeroLevelSet(grid, sample(grid, [](const Point& p) { return p.norm() - 0.8; }));
    const SurfaceTopology t = analyseSurface(mesh);
    EXPECT_TRUE(t.closedManifold()) << describe(t);
    EXPECT_EQ(t.components, 1);
    EXPECT_EQ(t.genus, 0);
    for (const Point& v : mesh.vertices) ASSERT_NEAR(v.norm(), 0.8, 0.1 * grid.spacing);
    // Counter-clockwise seen from outside: the enclosed volume is positive, about 4/3 pi r^3.
    EXPECT_NEAR(signedVolume(mesh), 4.0 / 3.0 * M_PI * std::pow(0.8, 3), 0.02);
}

TEST(IsoSurface, TorusFieldGivesGenusOne) {
    const FieldGrid grid = cube(40);
    const TriangleMesh mesh = extractZeroLevelSet(grid, sample(grid, [](const Point& p) {
        return std::hypot(std::hypot(p.x(), p.y()) - 0.7, p.z()) - 0.25;
    }));
    const SurfaceTopology t = analyseSurface(mesh);
    EXPECT_TRUE(t.closedManifold()) << describe(t);
    EXPECT_EQ(t.components, 1);
    EXPECT_EQ(t.genus, 1);
    EXPECT_NE(describe(t).find("genus 1"), std::string::npos) << describe(t);
}

TEST(IsoSurface, ZeroValuesOnGridNodesGiveNoDegenerateTriangle) {
    // A box whose faces pass exactly through grid nodes.
    const FieldGrid grid = cube(12);
    const TriangleMesh mesh = extractZeroLevelSet(grid, sample(grid, [&](const Point& p) {
        return p.lpNorm<Eigen::Infinity>() - 4 * grid.spacing;
    }));
    ASSERT_FALSE(mesh.triangles.empty());
    for (const auto& t : mesh.triangles) {
        const double area = (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]).norm();
        ASSERT_GT(area, 0.0);
    }
    EXPECT_TRUE(analyseSurface(mesh).closedManifold());
}

TEST(IsoSurface, AFieldWithoutZeroCrossingGivesNoTriangle) {
    const FieldGrid grid = cube(8);
    EXPECT_TRUE(extractZeroLevelSet(grid, std::vector<double>(grid.size(), 1.0)).triangles.empty());
}

TEST(IsoSurface, AFieldOfTheWrongSizeIsACallerError) {
    EXPECT_THROW(extractZeroLevelSet(cube(8), std::vector<double>(10, 1.0)), CallerError);
}

// A tetrahedron's surface, built by hand: the numbers are known.
TriangleMesh tetrahedron(const Point& offset) {
    TriangleMesh m;
    m.vertices = {offset + Point(0, 0, 0), offset + Point(1, 0, 0), offset + Point(0, 1, 0), offset + Point(0, 0, 1)};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return m;
}

TEST(SurfaceTopology, CountsComponentsBoundariesAndNonManifoldEdges) {
    TriangleMesh two = tetrahedron(Point::Zero());
    const TriangleMesh other = tetrahedron(Point(5, 0, 0));
    for (const Point& v : other.vertices) two.vertices.push_back(v);
    for (auto t : other.triangles) two.triangles.push_back({t[0] + 4, t[1] + 4, t[2] + 4});
    SurfaceTopology t = analyseSurface(two);
    EXPECT_EQ(t.components, 2);
    EXPECT_EQ(t.vertices, 8);
    EXPECT_EQ(t.triangles, 8);
    EXPECT_EQ(t.edges, 12);
    EXPECT_EQ(t.genus, 0);
    EXPECT_TRUE(t.closedManifold());

    TriangleMesh open = tetrahedron(Point::Zero());
    open.triangles.pop_back();
    t = analyseSurface(open);
    EXPECT_EQ(t.boundaryEdges, 3);
    EXPECT_FALSE(t.closedManifold());

    TriangleMesh fin = tetrahedron(Point::Zero());
    fin.vertices.push_back(Point(-1, -1, 0));
    fin.triangles.push_back({0, 1, 4});  // a third triangle on edge 0-1
    t = analyseSurface(fin);
    EXPECT_EQ(t.nonManifoldEdges, 1);
    EXPECT_FALSE(t.closedManifold());
}

}  // namespace
}  // namespace pcskeleton
