// PointIndex against brute force: the k nearest (nearest first, the point itself included),
// the balls, and the spatial order (a permutation of every point).
#include <pcskeleton/internal/spatial_index.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

using namespace pcskeleton;

namespace {

PointList randomPoints(std::size_t n, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    PointList points(n);
    for (Point& p : points) p = Point(coordinate(random), coordinate(random), coordinate(random));
    return points;
}

std::vector<double> sortedDistances(const PointList& points, const Point& centre) {
    std::vector<double> d;
    for (const Point& p : points) d.push_back((p - centre).norm());
    std::sort(d.begin(), d.end());
    return d;
}

}  // namespace

TEST(SpatialIndex, NearestAreTheBruteForceNearestInOrder) {
    const PointList points = randomPoints(2000, 1);
    const PointIndex index(points);
    const PointList queries = randomPoints(50, 2);
    std::vector<int> found;
    for (const Point& q : queries) {
        index.nearest(q, 12, found);
        ASSERT_EQ(found.size(), 12u);
        const std::vector<double> truth = sortedDistances(points, q);
        for (std::size_t i = 0; i < found.size(); ++i) {
            EXPECT_DOUBLE_EQ((points[found[i]] - q).norm(), truth[i]) << "neighbour " << i;
        }
    }
}

TEST(SpatialIndex, APointIsItsOwnNearestNeighbour) {
    const PointList points = randomPoints(500, 3);
    const PointIndex index(points);
    std::vector<int> found;
    for (int i : {0, 17, 499}) {
        index.nearest(points[i], 3, found);
        ASSERT_FALSE(found.empty());
        EXPECT_EQ(found.front(), i);
    }
}

TEST(SpatialIndex, MoreNeighboursThanPointsGivesEveryPoint) {
    const PointList points = randomPoints(7, 4);
    const PointIndex index(points);
    std::vector<int> found = {42};  // replaced, not appended to
    index.nearest(Point::Zero(), 20, found);
    std::sort(found.begin(), found.end());
    std::vector<int> all(7);
    std::iota(all.begin(), all.end(), 0);
    EXPECT_EQ(found, all);
}

TEST(SpatialIndex, BallsAreTheBruteForceBalls) {
    const PointList points = randomPoints(3000, 5);
    const PointIndex index(points);
    std::vector<int> found = {-1};
    for (double radius : {0.0, 0.05, 0.3, 5.0}) {
        for (const Point& centre : randomPoints(20, 6)) {
            index.withinRadius(centre, radius, found);
            std::sort(found.begin(), found.end());
            std::vector<int> truth;
            for (std::size_t i = 0; i < points.size(); ++i) {
                if ((points[i] - centre).norm() <= radius) truth.push_back(int(i));
            }
            // A point exactly on the sphere may go either way; random points are never on it.
            EXPECT_EQ(found, truth) << "radius " << radius;
        }
    }
}

TEST(SpatialIndex, SpatialOrderIsAPermutationThatKeepsNeighboursClose) {
    const PointList points = randomPoints(4000, 7);
    const PointIndex index(points);
    std::vector<std::size_t> order = index.spatialOrder();
    ASSERT_EQ(order.size(), points.size());
    double along = 0, input = 0;
    for (std::size_t i = 1; i < order.size(); ++i) {
        along += (points[order[i]] - points[order[i - 1]]).norm();
        input += (points[i] - points[i - 1]).norm();
    }
    // Consecutive points of a space-filling curve are near each other; random ones are not.
    EXPECT_LT(along, 0.25 * input);
    std::sort(order.begin(), order.end());
    for (std::size_t i = 0; i < order.size(); ++i) ASSERT_EQ(order[i], i);
}
