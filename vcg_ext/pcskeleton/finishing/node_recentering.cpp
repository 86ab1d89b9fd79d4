#include "pcskeleton/finishing/node_recentering.h"

#include <Eigen/Dense>

#include <algorithm>
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
// A tube shows in its neighbours too: its radius changes slowly along the bone, so the
// circles of neighbouring nodes agree, while the circle fitted across a curled sheet (a leaf
// across its width) follows the curl, which changes from node to node. Two circles agree
// when their radii are within this ratio (docs/benchmarks.md: chosen on the tuning half).
constexpr double kLargestRadiusRatio = 1.2;

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

// What a node's points across its bone look like.
struct CrossSection {
    enum Kind { kUnknown, kSurrounded, kWall, kSheet } kind = kUnknown;
    double radius = 0.0;  // kWall: the circle's
    Point centre;         // kWall: the circle's centre
};

CrossSection crossSection(int n, const SkeletonGraph& skeleton, const std::vector<int>& around,
                          const std::vector<int>& members, const PointList& points) {
    CrossSection section;
    if (around.empty() || around.size() > 2 || int(members.size()) < kMinimumPoints) return section;
    const PointList& nodes = skeleton.nodes;
    const Point axis =
        (around.size() == 2 ? nodes[around[1]] - nodes[around[0]] : nodes[around[0]] - nodes[n]).normalized();
    if (!axis.allFinite()) return section;
    const Point u = axis.unitOrthogonal(), v = axis.cross(u);
    std::vector<Eigen::Vector2d> across;
    for (int i : members) {
        const Point d = points[i] - nodes[n];
        across.emplace_back(d.dot(u), d.dot(v));
    }
    Circle circle;
    if (!fitCircle(across, circle) || circle.residual > kMaximumResidual) return section;
    Eigen::Vector2d side = Eigen::Vector2d::Zero();
    for (const Eigen::Vector2d& q : across) {
        if ((q - circle.centre).norm() > 0.0) side += (q - circle.centre).normalized();
    }
    const double arcResultant = side.norm() / double(across.size());
    if (arcResultant < kOneSided) section.kind = CrossSection::kSurrounded;  // the centroid is right
    else if (arcResultant > kLargestArcResultant) section.kind = CrossSection::kSheet;
    else if (circle.centre.norm() <= circle.radius) {  // else the node would leave its tube
        section.kind = CrossSection::kWall;
        section.radius = circle.radius;
        section.centre = nodes[n] + circle.centre.x() * u + circle.centre.y() * v;
    }
    return section;
}

bool circlesAgree(double a, double b) { return std::max(a / b, b / a) <= kLargestRadiusRatio; }

}  // namespace

RecenteringReport recentreOneSidedNodes(SkeletonGraph& skeleton, const PointList& points, const DataSupport& support) {
    RecenteringReport report;
    const std::size_t count = skeleton.nodeCount();
    const std::vector<std::vector<int>> adjacent = adjacencyLists(count, skeleton.edges);
    const std::vector<std::vector<int>> members = pointsOfNodes(skeleton);
    std::vector<CrossSection> sections(count);
    for (std::size_t n = 0; n < count; ++n) sections[n] = crossSection(int(n), skeleton, adjacent[n], members[n], points);
    // A wall node is contradicted by a neighbouring wall whose circle disagrees, and confirmed
    // by a neighbour that is a tube too: its points surround it, or its circle agrees and is
    // not contradicted itself. Along a curled sheet the circles drift from node to node, so
    // two of them may agree by chance, but not a whole stretch.
    const auto contradicted = [&](std::size_t n) {
        for (int m : adjacent[n]) {
            if (sections[m].kind == CrossSection::kWall && !circlesAgree(sections[n].radius, sections[m].radius))
                return true;
        }
        return false;
    };
    const auto confirmedByNeighbours = [&](std::size_t n) {
        if (contradicted(n)) return false;
        for (int m : adjacent[n]) {
            const CrossSection& neighbour = sections[m];
            if (neighbour.kind == CrossSection::kSurrounded) return true;
            if (neighbour.kind == CrossSection::kWall && !contradicted(std::size_t(m))) return true;
        }
        return false;
    };
    double shifts = 0.0;
    for (std::size_t n = 0; n < count; ++n) {
        const CrossSection& section = sections[n];
        if (section.kind != CrossSection::kWall) continue;
        if (!confirmedByNeighbours(n)) {
            ++report.unlikeNeighbours;
            continue;
        }
        if (!support.supports(section.centre, section.radius, members[n])) {
            ++report.refused;
            continue;
        }
        shifts += (section.centre - skeleton.nodes[n]).norm();
        skeleton.nodes[n] = section.centre;
        skeleton.radii[n] = section.radius;
        ++report.recentredNodes;
        report.nodes.push_back(int(n));
    }
    if (report.recentredNodes > 0) report.meanShift = shifts / report.recentredNodes;
    return report;
}

}  // namespace pcskeleton
