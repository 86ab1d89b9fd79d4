#include "pcskeleton/finishing/node_recentering.h"

#include <Eigen/Dense>

#include <cmath>

namespace pcskeleton {

namespace {

constexpr int kMinimumPoints = 8;
// Points around their circle leave the mean of the unit vectors towards them near 0; a
// half circle gives 0.64. Below this the centroid is already the centre.
constexpr double kOneSided = 0.3;
constexpr double kMaximumResidual = 0.2;  // RMS distance to the circle, share of its radius
// Points spread over an arc of angle a leave a mean unit vector of length sin(a/2)/(a/2),
// seen from the arc's centre: 0.64 for a half circle, 0.90 for a quarter. A slightly curved
// sheet (a leaf, a plate) fits a huge circle over a small arc, whose centre is far from any
// data: above this the points are a sheet, not a part of a tube's wall.
constexpr double kLargestArcResultant = 0.9;

struct Circle {
    Eigen::Vector2d centre;
    double radius = 0.0, residual = 0.0;
};

// Kasa's fit: x^2 + y^2 + D x + E y + F = 0 in least squares (linear in D, E, F).
bool fitCircle(const std::vector<Eigen::Vector2d>& q, Circle& circle) {
    Eigen::MatrixX3d a(q.size(), 3);
    Eigen::VectorXd b(q.size());
    for (std::size_t i = 0; i < q.size(); ++i) {
        a.row(Eigen::Index(i)) << q[i].x(), q[i].y(), 1.0;
        b(Eigen::Index(i)) = -q[i].squaredNorm();
    }
    const Eigen::Vector3d s = a.colPivHouseholderQr().solve(b);
    circle.centre = -0.5 * s.head<2>();
    const double squared = circle.centre.squaredNorm() - s(2);
    if (!(squared > 0.0) || !s.allFinite()) return false;
    circle.radius = std::sqrt(squared);
    double sum = 0.0;
    for (const Eigen::Vector2d& p : q) sum += std::pow((p - circle.centre).norm() - circle.radius, 2);
    circle.residual = std::sqrt(sum / double(q.size())) / circle.radius;
    return true;
}

}  // namespace

RecenteringReport recentreOneSidedNodes(SkeletonGraph& skeleton, const PointList& points, const DataSupport& support) {
    RecenteringReport report;
    const std::vector<std::vector<int>> adjacent = adjacencyLists(skeleton.nodeCount(), skeleton.edges);
    const std::vector<std::vector<int>> members = pointsOfNodes(skeleton);
    const PointList before = skeleton.nodes;
    double shifts = 0.0;
    for (std::size_t n = 0; n < skeleton.nodeCount(); ++n) {
        const std::vector<int>& around = adjacent[n];
        if (around.empty() || around.size() > 2 || int(members[n].size()) < kMinimumPoints) continue;
        const Point axis = (around.size() == 2 ? before[around[1]] - before[around[0]] : before[around[0]] - before[n])
                               .normalized();
        if (!axis.allFinite()) continue;
        const Point u = axis.unitOrthogonal(), v = axis.cross(u);
        std::vector<Eigen::Vector2d> across;
        for (int i : members[n]) {
            const Point d = points[i] - before[n];
            across.emplace_back(d.dot(u), d.dot(v));
        }
        Circle circle;
        if (!fitCircle(across, circle) || circle.residual > kMaximumResidual) continue;
        Eigen::Vector2d side = Eigen::Vector2d::Zero();
        for (const Eigen::Vector2d& q : across) {
            if ((q - circle.centre).norm() > 0.0) side += (q - circle.centre).normalized();
        }
        const double arcResultant = side.norm() / double(across.size());
        if (arcResultant < kOneSided) continue;             // surrounded: the centroid is right
        if (arcResultant > kLargestArcResultant) continue;  // a sheet, not a tube
        if (circle.centre.norm() > circle.radius) continue; // the node would leave its tube
        const Point centre = before[n] + circle.centre.x() * u + circle.centre.y() * v;
        if (!support.supports(centre, circle.radius, members[n])) {
            ++report.refused;
            continue;
        }
        skeleton.nodes[n] = centre;
        skeleton.radii[n] = circle.radius;
        shifts += circle.centre.norm();
        ++report.recentredNodes;
        report.nodes.push_back(int(n));
    }
    if (report.recentredNodes > 0) report.meanShift = shifts / report.recentredNodes;
    return report;
}

}  // namespace pcskeleton
