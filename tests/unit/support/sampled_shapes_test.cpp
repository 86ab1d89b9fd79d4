// The test fixtures' sheets: a map of the unit square triangulated with its holes left out,
// its area, and points uniform by area on it.
#include "support/sampled_shapes.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pcskeleton;

TEST(SampledShapes, ASheetIsItsMapsImageWithoutItsHoles) {
    const auto square = [](double u, double v) { return Point(2 * u, 3 * v, 1); };
    const auto hole = [](double u, double v) { return std::hypot(u - 0.5, v - 0.5) > 0.25; };
    const shapes::Triangles full = shapes::sheet(square, 40, 40);
    const shapes::Triangles holed = shapes::sheet(square, 40, 40, hole);
    EXPECT_EQ(full.size(), 2u * 40 * 40);
    EXPECT_NEAR(shapes::area(full), 6.0, 1e-9);
    // A hole of radius 0.25 in the unit square, stretched by 2 x 3: about 6 pi / 16.
    EXPECT_NEAR(shapes::area(full) - shapes::area(holed), 6 * M_PI / 16, 0.1);

    const PointList points = shapes::sample(holed, 5000, 3);
    ASSERT_EQ(points.size(), 5000u);
    int left = 0;
    for (const Point& p : points) {
        EXPECT_NEAR(p.z(), 1.0, 1e-12);
        EXPECT_GT(std::hypot(p.x() / 2 - 0.5, p.y() / 3 - 0.5), 0.22) << "a point in the hole";
        left += p.x() < 1.0;
    }
    EXPECT_NEAR(left, 2500, 150) << "uniform by area";
    EXPECT_EQ(shapes::sample(holed, 5000, 3), points) << "the same seed, the same points";
}
