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
// A tube's wall curves evenly: each half of its arc fits a circle close to the whole arc's.
// The factors by which the two halves' radii differ from the whole's (each taken at least 1),
// multiplied, stay below this on a tube seen from one side (docs/benchmarks.md: chosen on the
// tuning half), while a leaf folded along its midrib has nearly straight halves.
constexpr double kLargestCurvatureFactor = 4.0;

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

// Whether the points across a bone curve evenly round `circle`, their fit: the arc split at
// the middle of its angle round the circle's centre, each half fitted on its own.
bool evenlyCurved(const std::vector<Eigen::Vector2d>& across, const Circle& circle) {
    std::vector<double> angles;
    for (const Eigen::Vector2d& q : across) angles.push_back(std::atan2(q.y() - circle.centre.y(), q.x() - circle.centre.x()));
    std::vector<double> sorted = angles;
    std::sort(sorted.begin(), sorted.end());
    // The arc starts where the widest gap between neighbouring angles ends.
    double start = sorted.front(), widest = sorted.front() + 2.0 * M_PI - sorted.back();
    for (std::size_t i = 1; i < sorted.size(); ++i) {
        if (sorted[i] - sorted[i - 1] > widest) widest = sorted[i] - sorted[i - 1], start = sorted[i];
    }
    const double middle = 0.5 * (2.0 * M_PI - widest);
    std::vector<Eigen::Vector2d> halves[2];
    for (std::size_t i = 0; i < across.size(); ++i) {
        const double along = std::fmod(angles[i] - start + 4.0 * M_PI, 2.0 * M_PI);
        halves[along < middle ? 0 : 1].push_back(across[i]);
    }
    double factor = 1.0;
    for (const std::vector<Eigen::Vector2d>& half : halves) {
        if (half.size() < 4) return true;  // any three points fit a circle: nothing to tell
        Circle fitted;
        if (!fitCircle(half, fitted)) return false;  // a straight half
        factor *= std::max(fitted.radius / circle.radius, circle.radius / fitted.radius);
    }
    return factor <= kLargestCurvatureFactor;
}

// What a node's points across its bone look like.
struct CrossSection {
    enum Kind { kUnknown, kSurrounded, kWall, kFolded, kSheet } kind = kUnknown;
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
    else if (circle.centre.norm() > circle.radius) return section;  // the node would leave its tube
    else if (!evenlyCurved(across, circle)) section.kind = CrossSection::kFolded;
    else {
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
    // A wall node is contradicted by a neighbouring wall whose circle disagrees or by a folded
    // neighbour (a leaf runs on, and not each of its sections folds), and confirmed by a
    // neighbour that is a tube too: its points surround it, or its circle agrees and is not
    // contradicted itself. Along a curled sheet the circles drift from node to node, so two
    // of them may agree by chance, but not a whole stretch.
    const auto contradicted = [&](std::size_t n) {
        for (int m : adjacent[n]) {
            if (sections[m].kind == CrossSection::kFolded) return true;
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
        report.foldedSheets += section.kind == CrossSection::kFolded;
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
