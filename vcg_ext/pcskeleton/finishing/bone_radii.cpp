#include "pcskeleton/finishing/bone_radii.h"

#include "pcskeleton/finishing/data_support.h"
#include "pcskeleton/internal/median.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcskeleton {

namespace {

// Fewer points give a variance too uncertain to subtract.
constexpr std::size_t kMinimumPoints = 8;
// Points around the bone leave the mean of the unit vectors towards them (across the bone)
// near 0; a half circle gives 0.64. Above this the points lie to one side (re-centring's
// test, node_recentering.cpp), and the correction, which assumes they surround the axis,
// does not hold.
constexpr double kSurrounded = 0.3;
// A cross-section flatter than this (its narrower second moment against its wider, as a
// ratio of lengths) is a sheet's or a plate's, whose "radius" is no tube's: the correction
// would only shrink it.
constexpr double kFlattest = 0.5;
// The moments are not robust: one stray point adds far more to Var[d] than to E[d]. Points
// beyond kTrim deviations of the median (from the median absolute deviation) are left
// out; trimming a Gaussian there changes its variance by under 3%.
constexpr double kTrim = 3.0;
constexpr double kDeviationsPerMad = 1.4826;  // a Gaussian's deviation per median absolute deviation

// The radius of node n's bone from the distances of its points across the bone, or 0.
double boneRadius(const SkeletonGraph& skeleton, std::size_t n, const std::vector<int>& around,
                  const std::vector<int>& members, const PointList& points, double nodeSpacing) {
    if (around.size() != 2 || members.size() < kMinimumPoints) return 0.0;
    const Point& node = skeleton.nodes[n];
    const Point axis = (skeleton.nodes[std::size_t(around[1])] - skeleton.nodes[std::size_t(around[0])]).normalized();
    if (!axis.allFinite()) return 0.0;
    // One pass over the points (scattered through a large cloud): each one's offset across
    // the bone, in the plane's coordinates, and its distance from the node.
    const Point u = axis.unitOrthogonal(), v = axis.cross(u);
    std::vector<Eigen::Vector2d> across;
    across.reserve(members.size());
    double nearestSquared = std::numeric_limits<double>::infinity();
    for (int i : members) {
        const Point q = points[std::size_t(i)] - node;
        across.emplace_back(q.dot(u), q.dot(v));
        nearestSquared = std::min(nearestSquared, q.squaredNorm());
    }
    const double nearestPoint = std::sqrt(nearestSquared);
    std::vector<double> distances;
    distances.reserve(across.size());
    Eigen::Vector2d towards = Eigen::Vector2d::Zero();
    Eigen::Matrix2d moments = Eigen::Matrix2d::Zero();
    for (const Eigen::Vector2d& a : across) {
        const double d = a.norm();
        if (d > 0.0) towards += a / d;
        distances.push_back(d);
        moments += a * a.transpose();
    }
    if (towards.norm() > kSurrounded * double(members.size())) return 0.0;
    const Eigen::Vector2d extent = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(moments).eigenvalues();
    if (!(extent(0) >= kFlattest * kFlattest * extent(1))) return 0.0;

    const double middle = median(distances);
    std::vector<double> deviations;
    for (double d : distances) deviations.push_back(std::abs(d - middle));
    const double spread = kTrim * kDeviationsPerMad * median(deviations);
    double sum = 0.0, squares = 0.0, nearestAcross = std::numeric_limits<double>::infinity();
    std::size_t kept = 0;
    for (double d : distances) {
        if (spread > 0.0 && std::abs(d - middle) > spread) continue;
        sum += d, squares += d * d, nearestAcross = std::min(nearestAcross, d), ++kept;
    }
    const double mean = sum / double(kept), meanSquare = squares / double(kept);
    // E[d^2] - 2 Var[d] = 2 E[d]^2 - E[d^2], at most E[d]. Noise puts some points inside the
    // tube: when every point lies outside the radius this gives, the points are no tube's
    // wall around this bone (a bend, where two parts meet, a flat section). (Points all at
    // one distance give it exactly, up to rounding.)
    const double squared = 2.0 * mean * mean - meanSquare;
    if (!(squared >= nearestAcross * nearestAcross * (1.0 - 1e-9))) return 0.0;
    const double radius = std::sqrt(squared);
    // Nor may the radius leave the node farther from its points than the invariant allows
    // (data_support.h); the node does not move, so it stays inside the box.
    if (nearestPoint > radius + kSupportSlack * nodeSpacing) return 0.0;
    return radius;
}

}  // namespace

std::vector<double> boneRadii(const SkeletonGraph& skeleton, const PointList& points, double nodeSpacing) {
    const std::size_t count = skeleton.nodeCount();
    const std::vector<std::vector<int>> adjacent = adjacencyLists(count, skeleton.edges);
    const std::vector<std::vector<int>> members = pointsOfNodes(skeleton);
    std::vector<double> radii(count, 0.0);
    // Nodes of a large cloud own very different numbers of points.
#pragma omp parallel for schedule(dynamic)
    for (long n = 0; n < long(count); ++n) {
        const std::size_t node = std::size_t(n);
        radii[node] = boneRadius(skeleton, node, adjacent[node], members[node], points, nodeSpacing);
    }
    return radii;
}

void measureBoneRadii(SkeletonGraph& skeleton, const PointList& points, double nodeSpacing) {
    const std::vector<double> radii = boneRadii(skeleton, points, nodeSpacing);
    for (std::size_t n = 0; n < radii.size(); ++n) {
        if (radii[n] > 0.0) skeleton.radii[n] = radii[n];
    }
}

}  // namespace pcskeleton
