#include "pcskeleton/skeleton/skeleton_structure.h"

#include "pcskeleton/internal/disjoint_sets.h"
#include "pcskeleton/internal/local_plane.h"
#include "pcskeleton/internal/median.h"
#include "pcskeleton/internal/spatial_index.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>

namespace pcskeleton {

namespace {

// Share of a limb's points that must lie in the other nodes' tubes for the limb to be
// redundant: a few points of a real limb can be close to the body (its base), and noise
// puts a few of a redundant one outside.
constexpr double kCoveredShare = 0.9;
// A node whose points lie across a flat strip (their second spread at most kStripSpread of
// the first: a leaf or plate along its mid-line) holds in its tube the points out to the
// strip's edge, all but the farthest tenth (kStripReachQuantile); its radius, a mean
// distance, reaches about half as far. A tube's cross-section is a ring, whose two larger
// spreads are equal, and a half tube's (one view) differ by a factor of about 5. A strip
// lies across the skeleton: its width within kStripAcross (the cosine of 60 degrees) of
// square to every bone at the node. A thin tube's node, whose points spread along its
// bones, is no strip, nor is a node shared by two limbs side by side, whose bones go out
// along the width to them.
constexpr double kStripSpread = 0.05;
constexpr double kStripAcross = 0.5;
constexpr double kStripReachQuantile = 0.9;
// A node at a limb's end owning fewer than this share of the points of the skeleton's
// median node is a straggler (stragglingEnds).
constexpr double kStragglerShare = 0.1;
// A limb's end is hooked (stragglingEnds) where its bone onwards turns more than 60 degrees
// (cosine below this) from the bone behind it. One bone each: the chord over several would
// see a tightly curled limb's end turn as much.
constexpr double kHookCosine = 0.5;
// A junction of three or four bones is a through junction when two of the bones other than
// the one judged meet at more than 120 degrees (cosine below this), straighter than a
// symmetric Y: a strand runs on through it and the judged bone leaves it from the side
// (docs/benchmarks.md#measurements-behind-the-constants).
constexpr double kThroughCosine = -0.5;
// The chain runs on from both ends of a U-turn bridge within 60 degrees of the same
// direction (cosine above this): the parts it joins lie side by side.
constexpr double kSameWayCosine = 0.5;
// Corner limbs (isCornerLimb). The arms are read over this many bones from the junction,
// as gap bridging reads a limb's direction: one bone zig-zags with the nodes' placement.
constexpr std::size_t kCornerArmBones = 4;
// The arms bend: they meet at 135 degrees or less (cosine above this); a straight tube's
// meet at 180.
constexpr double kCornerBendCosine = -0.7071;
// The limb leaves into the outer corner: within 60 degrees (cosine above this) of the
// direction away from both arms.
constexpr double kCornerAimCosine = 0.5;
// The limb is about as thick as the arms: its median radius at least this share of the
// thinner arm's. A bend's outer wall belongs to the arms' own tube; a real limb off a thick
// body is thinner than the body (docs/benchmarks.md).
constexpr double kCornerThickness = 0.4;
// How far the limb's points reach from the junction: all but the farthest tenth (noise).
constexpr double kCornerReachQuantile = 0.9;
// The limb ends within this many times the reach of a mitred bend of the thinner arm's
// tube, r / sin(half the bend angle): the skeleton cuts the corner, so the junction lies
// inside the bend, and noise widens the wall. The half angle is taken as 30 degrees at
// least (a reach of at most 2 r): arms that leave the junction side by side make no corner
// whose reach grows without bound.
constexpr double kCornerSlack = 1.5;
constexpr double kCornerMinHalfBendSine = 0.5;

double boneLength(const SkeletonGraph& graph, int a, int b) { return (graph.nodes[a] - graph.nodes[b]).norm(); }

// The median number of points of the nodes that own any (0 when none does).
double medianPointsPerNode(const std::vector<std::vector<int>>& nodePoints) {
    std::vector<double> counts;
    for (const std::vector<int>& owned : nodePoints) {
        if (!owned.empty()) counts.push_back(double(owned.size()));
    }
    return counts.empty() ? 0.0 : median(std::move(counts));
}

// The paths through nodes of degree 2 from a junction to another junction, each once
// (from its lower-numbered junction); a path back to its own junction is not one.
std::vector<std::vector<int>> junctionToJunctionPaths(const std::vector<std::vector<int>>& neighbours) {
    std::vector<std::vector<int>> paths;
    for (std::size_t junction = 0; junction < neighbours.size(); ++junction) {
        if (neighbours[junction].size() < 3) continue;
        for (int next : neighbours[junction]) {
            std::vector<int> path = walkChain(neighbours, int(junction), next);
            const int end = path.back();
            if (end > int(junction) && neighbours[end].size() >= 3) paths.push_back(std::move(path));
        }
    }
    return paths;
}

// Shortest path by bone length from `source` to `target` without the bone source-target;
// empty when there is none.
std::vector<int> shortestDetour(const SkeletonGraph& graph, const std::vector<std::vector<int>>& neighbours,
                                int source, int target) {
    const double infinity = std::numeric_limits<double>::infinity();
    std::vector<double> distance(graph.nodeCount(), infinity);
    std::vector<int> previous(graph.nodeCount(), -1);
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    distance[source] = 0.0;
    queue.push({0.0, source});
    while (!queue.empty()) {
        const auto [d, n] = queue.top();
        queue.pop();
        if (n == target) break;
        if (d > distance[n]) continue;
        for (int m : neighbours[n]) {
            if (n == source && m == target) continue;
            const double through = d + boneLength(graph, n, m);
            if (through < distance[m]) distance[m] = through, previous[m] = n, queue.push({through, m});
        }
    }
    std::vector<int> path;
    if (distance[target] == infinity) return path;
    for (int n = target; n != -1; n = previous[n]) path.push_back(n);
    std::reverse(path.begin(), path.end());
    return path;
}

// Whether `junction` has three or four bones, two of which, other than the one to `branch`,
// meet at more than 120 degrees (kThroughCosine): a strand runs on through it. (Four: two
// strands that meet at a crossing, or a strand and a branch; on the robustness suite they
// right the knot scanned from four views, whose false loops close at such junctions.)
bool isThroughJunction(const SkeletonGraph& graph, const std::vector<std::vector<int>>& neighbours, int junction,
                       int branch) {
    if (neighbours[junction].size() != 3 && neighbours[junction].size() != 4) return false;
    std::vector<Point> ways;
    for (int m : neighbours[junction]) {
        if (m != branch) ways.push_back((graph.nodes[m] - graph.nodes[junction]).normalized());
    }
    for (std::size_t i = 0; i < ways.size(); ++i) {
        for (std::size_t j = i + 1; j < ways.size(); ++j) {
            if (ways[i].dot(ways[j]) < kThroughCosine) return true;
        }
    }
    return false;
}

// U-turn bridges (strayBridges): each run of consecutive nodes of degree 2 that together own
// fewer than `fewest` points, between two nodes of degree 2 from which the chain runs on
// the same way; given with those two nodes at its ends. A run that closes on itself is
// not one.
std::vector<std::vector<int>> uTurnBridges(const SkeletonGraph& graph, const std::vector<std::vector<int>>& neighbours,
                                           const std::vector<std::vector<int>>& nodePoints, double fewest) {
    const auto few = [&](int n) { return neighbours[n].size() == 2 && double(nodePoints[n].size()) < fewest; };
    // From `end`, away from `from`: the way the chain runs on (zero past a junction or tip).
    const auto onward = [&](int end, int from) -> Point {
        if (neighbours[end].size() != 2) return Point::Zero();
        const int next = neighbours[end][0] == from ? neighbours[end][1] : neighbours[end][0];
        return (graph.nodes[next] - graph.nodes[end]).normalized();
    };
    std::vector<std::vector<int>> bridges;
    std::vector<bool> seen(graph.nodeCount(), false);
    for (std::size_t first = 0; first < graph.nodeCount(); ++first) {
        if (seen[first] || !few(int(first))) continue;
        // Grow the run both ways; ends[side] is the first node past it on that side.
        std::vector<int> run{int(first)};
        seen[first] = true;
        int ends[2] = {-1, -1};
        bool closed = false;
        for (int side = 0; side < 2 && !closed; ++side) {
            int previous = int(first), current = neighbours[first][side];
            while (few(current) && !closed) {
                closed = seen[current];
                seen[current] = true;
                run.insert(side == 0 ? run.begin() : run.end(), current);
                const int ahead = neighbours[current][0] == previous ? neighbours[current][1] : neighbours[current][0];
                previous = current, current = ahead;
            }
            ends[side] = current;
        }
        if (closed || ends[0] == ends[1]) continue;
        double runPoints = 0.0;
        for (int n : run) runPoints += double(nodePoints[n].size());
        if (runPoints >= fewest) continue;
        if (onward(ends[0], run.front()).dot(onward(ends[1], run.back())) > kSameWayCosine) {
            run.insert(run.begin(), ends[0]);
            run.push_back(ends[1]);
            bridges.push_back(std::move(run));
        }
    }
    return bridges;
}

}  // namespace

std::vector<int> walkChain(const std::vector<std::vector<int>>& neighbours, int from, int next) {
    std::vector<int> path{from};
    int previous = from, current = next;
    while (true) {
        path.push_back(current);
        if (neighbours[current].size() != 2 || current == from) return path;
        const int ahead = neighbours[current][0] == previous ? neighbours[current][1] : neighbours[current][0];
        previous = current, current = ahead;
    }
}

Point chainDirection(const SkeletonGraph& graph, const std::vector<int>& chain, std::size_t bones) {
    const Point along = graph.nodes[std::size_t(chain[std::min(bones, chain.size() - 1)])] -
                        graph.nodes[std::size_t(chain.front())];
    return along.norm() > 0.0 ? Point(along.normalized()) : Point(Point::Zero());
}

double pathLength(const SkeletonGraph& graph, const std::vector<int>& path) {
    double length = 0.0;
    for (std::size_t i = 1; i < path.size(); ++i) length += boneLength(graph, path[i - 1], path[i]);
    return length;
}

std::vector<Limb> tipLimbs(const SkeletonGraph& graph) {
    const auto neighbours = adjacencyLists(graph.nodeCount(), graph.edges);
    std::vector<Limb> limbs;
    for (std::size_t tip = 0; tip < graph.nodeCount(); ++tip) {
        if (neighbours[tip].size() != 1) continue;
        Limb limb;
        limb.path = walkChain(neighbours, int(tip), neighbours[tip][0]);
        limb.length = pathLength(graph, limb.path);
        limb.atJunction = neighbours[limb.path.back()].size() >= 3;
        limbs.push_back(std::move(limb));
    }
    return limbs;
}

bool isSpur(const SkeletonGraph& graph, const Limb& limb, double nodeSpacing) {
    if (!limb.atJunction) return false;  // a whole component, not a spur of something
    return limb.length < std::max(graph.radii[limb.path.back()], nodeSpacing);
}

namespace {

// The hooked end of a limb: the nodes from the tip up to the node where the limb turns
// off its way (its bone onwards turns from the bone behind it), all within that node's tube
// (its radius plus a node spacing) and owning fewer points together than that node. Noise
// points gathered at the side of a limb's end make such a hook, which would send tip
// extension across the limb; a limb's own end owns its cap's points. Returns the number
// of nodes before that node, 0 for a limb without a hook.
std::size_t hookLength(const SkeletonGraph& graph, const std::vector<std::vector<int>>& nodePoints, const Limb& limb,
                       double nodeSpacing) {
    std::size_t hookPoints = 0;
    for (std::size_t turn = 1; turn + 1 < limb.path.size(); ++turn) {
        const int node = limb.path[turn];
        const Point& at = graph.nodes[node];
        const double reach = graph.radii[node] + nodeSpacing;
        const auto outOfTube = [&](int n) { return (graph.nodes[n] - at).norm() > reach; };
        if (std::any_of(limb.path.begin(), limb.path.begin() + std::ptrdiff_t(turn), outOfTube)) return 0;
        hookPoints += nodePoints[limb.path[turn - 1]].size();
        const Point onward = (at - graph.nodes[limb.path[turn + 1]]).normalized();
        const Point hook = (graph.nodes[limb.path[turn - 1]] - at).normalized();
        // Eigen leaves a zero vector as it is when normalised: coincident nodes make no turn.
        if (!onward.isZero() && !hook.isZero() && onward.dot(hook) < kHookCosine) {
            return hookPoints < nodePoints[node].size() ? turn : 0;
        }
    }
    return 0;
}

}  // namespace

std::vector<std::vector<int>> stragglingEnds(const SkeletonGraph& graph,
                                             const std::vector<std::vector<int>>& nodePoints, double nodeSpacing) {
    const double fewest = kStragglerShare * medianPointsPerNode(nodePoints);
    if (!(fewest > 0)) return {};
    const auto owns = [&](int n) { return double(nodePoints[n].size()); };

    std::vector<std::vector<int>> ends;
    for (const Limb& limb : tipLimbs(graph)) {
        // The first node from the tip that owns enough points keeps them all. The node the
        // limb ends at may keep them only if all the limb's nodes together own too few: a
        // thin limb has few points per node, but not in all.
        const auto keeper = std::find_if(limb.path.begin(), limb.path.end(), [&](int n) { return owns(n) >= fewest; });
        if (keeper == limb.path.begin()) {
            const std::size_t hook = hookLength(graph, nodePoints, limb, nodeSpacing);
            if (hook > 0) ends.emplace_back(limb.path.begin(), limb.path.begin() + std::ptrdiff_t(hook) + 1);
            continue;
        }
        if (keeper == limb.path.end()) continue;
        if (keeper + 1 == limb.path.end()) {
            double limbPoints = 0.0;
            for (auto n = limb.path.begin(); n != keeper; ++n) limbPoints += owns(*n);
            if (!limb.atJunction || limbPoints >= fewest) continue;
        }
        const double reach = graph.radii[*keeper] + 2.0 * nodeSpacing;
        const bool near = std::all_of(limb.path.begin(), keeper,
                                      [&](int n) { return (graph.nodes[n] - graph.nodes[*keeper]).norm() <= reach; });
        if (near) ends.emplace_back(limb.path.begin(), keeper + 1);
    }
    return ends;
}

std::vector<std::vector<int>> strayBridges(const SkeletonGraph& graph, const std::vector<std::vector<int>>& nodePoints) {
    const double fewest = kStragglerShare * medianPointsPerNode(nodePoints);
    const auto neighbours = adjacencyLists(graph.nodeCount(), graph.edges);
    std::vector<std::vector<int>> bridges;
    for (std::vector<int>& path : junctionToJunctionPaths(neighbours)) {
        if (path.size() < 3) continue;
        double innerPoints = 0.0;
        for (std::size_t i = 1; i + 1 < path.size(); ++i) innerPoints += double(nodePoints[path[i]].size());
        if (innerPoints >= fewest) continue;
        // On a loop: the junctions stay joined without the path. Side by side: the parts
        // it joins run on past both its ends, so they were two parts already.
        const bool onLoop = !shortestDetour(graph, neighbours, path[0], path[1]).empty();
        const bool sideBySide = isThroughJunction(graph, neighbours, path.front(), path[1]) &&
                                isThroughJunction(graph, neighbours, path.back(), path[path.size() - 2]);
        if (onLoop || sideBySide) bridges.push_back(std::move(path));
    }
    for (std::vector<int>& path : uTurnBridges(graph, neighbours, nodePoints, fewest)) {
        bridges.push_back(std::move(path));
    }
    return bridges;
}

std::vector<Edge> bonesAcrossGaps(const SkeletonGraph& graph, double nodeSpacing, double minStretch) {
    if (!(minStretch > 0)) return {};
    const auto neighbours = adjacencyLists(graph.nodeCount(), graph.edges);
    std::vector<std::pair<double, Edge>> found;  // (minus the stretch, bone)
    for (const Edge& bone : graph.edges) {
        const double radii = graph.radii[bone[0]] + graph.radii[bone[1]];
        if (radii < nodeSpacing) continue;  // thin tubes: any bone is longer than their radii
        const double stretch = boneLength(graph, bone[0], bone[1]) / radii;
        if (!(stretch > minStretch)) continue;
        if (!isThroughJunction(graph, neighbours, bone[0], bone[1]) ||
            !isThroughJunction(graph, neighbours, bone[1], bone[0])) {
            continue;
        }
        if (!shortestDetour(graph, neighbours, bone[0], bone[1]).empty()) found.push_back({-stretch, bone});
    }
    std::sort(found.begin(), found.end());
    std::vector<Edge> bones;
    for (const auto& [minusStretch, bone] : found) bones.push_back(bone);
    return bones;
}

namespace {

PointList pointsAt(const PointList& points, const std::vector<int>& indices) {
    PointList chosen;
    chosen.reserve(indices.size());
    for (int i : indices) chosen.push_back(points[std::size_t(i)]);
    return chosen;
}

// The median distance from a point of `cloud` (two or more) to its nearest other one.
double medianSpacing(const PointList& cloud) {
    const PointIndex index(cloud);
    std::vector<double> nearest;
    nearest.reserve(cloud.size());
    std::vector<int> found;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        index.nearest(cloud[i], 2, found);
        const int other = found[0] == int(i) ? found[1] : found[0];
        nearest.push_back((cloud[std::size_t(other)] - cloud[i]).norm());
    }
    return median(std::move(nearest));
}

// The shortest distance from a point of `a` to one of `b` (neither empty).
double closestApproach(const PointList& a, const PointList& b) {
    const PointIndex index(b);
    double closest = std::numeric_limits<double>::infinity();
    std::vector<int> found;
    for (const Point& p : a) {
        index.nearest(p, 1, found);
        closest = std::min(closest, (b[std::size_t(found[0])] - p).norm());
    }
    return closest;
}

}  // namespace

std::vector<Edge> bonesOverDataGaps(const SkeletonGraph& graph, const PointList& points,
                                    const std::vector<std::vector<int>>& nodePoints, double minStretch) {
    constexpr std::size_t kFewestPoints = 3;
    if (!(minStretch > 0) || graph.pointNode.size() != points.size()) return {};
    const auto neighbours = adjacencyLists(graph.nodeCount(), graph.edges);
    const auto isJunction = [&](int n) { return neighbours[std::size_t(n)].size() >= 3; };
    const auto inChain = [&](int n) { return neighbours[std::size_t(n)].size() == 2; };
    std::vector<std::pair<double, Edge>> found;  // (minus the gap in spacings, bone)
    for (const Edge& bone : graph.edges) {
        const bool limbEnd = (isJunction(bone[0]) && inChain(bone[1])) || (isJunction(bone[1]) && inChain(bone[0]));
        if (!limbEnd) continue;
        const double radii = graph.radii[bone[0]] + graph.radii[bone[1]];
        if (!(boneLength(graph, bone[0], bone[1]) > minStretch * radii)) continue;
        if (nodePoints[bone[0]].size() < kFewestPoints || nodePoints[bone[1]].size() < kFewestPoints) {
            continue;  // too few for a spacing
        }
        if (shortestDetour(graph, neighbours, bone[0], bone[1]).empty()) continue;  // not on a loop
        const PointList a = pointsAt(points, nodePoints[bone[0]]), b = pointsAt(points, nodePoints[bone[1]]);
        PointList both = a;
        both.insert(both.end(), b.begin(), b.end());
        const double spacing = medianSpacing(both);
        const double gap = closestApproach(a, b) / spacing;
        if (spacing > 0 && gap > kDataGapSpacings) found.push_back({-gap, bone});
    }
    std::sort(found.begin(), found.end());
    std::vector<Edge> bones;
    for (const auto& [minusGap, bone] : found) bones.push_back(bone);
    return bones;
}

namespace {

// How far from node `n` its tube reaches (isRedundantLimb): its radius, or, across a flat
// strip, the distance within which most of its points lie.
double tubeReach(const SkeletonGraph& graph, const std::vector<std::vector<int>>& neighbours, int n,
                 const PointList& points, const std::vector<std::vector<int>>& nodePoints) {
    const std::vector<int>& own = nodePoints[std::size_t(n)];
    const double radius = graph.radii[std::size_t(n)];
    if (own.size() < 3) return radius;
    const LocalPlane plane = fitLocalPlane(points, own);
    if (plane.variances(1) > kStripSpread * plane.variances(2)) return radius;
    const Point width = plane.axes.col(2);
    for (int m : neighbours[std::size_t(n)]) {
        const Point bone = (graph.nodes[std::size_t(m)] - graph.nodes[std::size_t(n)]).normalized();
        if (std::abs(bone.dot(width)) > kStripAcross) return radius;
    }
    std::vector<double> distances;
    distances.reserve(own.size());
    for (int p : own) distances.push_back((points[std::size_t(p)] - graph.nodes[std::size_t(n)]).norm());
    return std::max(radius, quantile(std::move(distances), kStripReachQuantile));
}

}  // namespace

bool isRedundantLimb(const SkeletonGraph& graph, const Limb& limb, const PointList& points,
                     const std::vector<std::vector<int>>& nodePoints, double nodeSpacing) {
    if (!limb.atJunction || graph.pointNode.size() != points.size()) return false;
    std::vector<bool> onLimb(graph.nodeCount(), false);
    for (std::size_t i = 0; i + 1 < limb.path.size(); ++i) onLimb[limb.path[i]] = true;  // the junction stays
    // Only nodes near the junction can hold the limb's points in their tubes.
    const Point& junction = graph.nodes[limb.path.back()];
    const double maxRadius = *std::max_element(graph.radii.begin(), graph.radii.end());
    const double reach = limb.length + 2.0 * maxRadius + nodeSpacing;
    std::vector<int> others;
    for (std::size_t n = 0; n < graph.nodeCount(); ++n) {
        if (!onLimb[n] && (graph.nodes[n] - junction).norm() <= reach) others.push_back(int(n));
    }
    std::size_t limbPoints = 0;
    for (std::size_t i = 0; i + 1 < limb.path.size(); ++i) limbPoints += nodePoints[limb.path[i]].size();
    if (limbPoints == 0) return false;
    const auto neighbours = adjacencyLists(graph.nodeCount(), graph.edges);
    std::vector<double> reachOf(graph.nodeCount(), 0.0);
    for (int n : others) reachOf[std::size_t(n)] = tubeReach(graph, neighbours, n, points, nodePoints) + nodeSpacing;
    // A real limb is usually told after a few of its points: stop once too many are outside.
    const double allowedOutside = (1.0 - kCoveredShare) * double(limbPoints);
    std::size_t outside = 0;
    for (std::size_t i = 0; i + 1 < limb.path.size(); ++i) {
        for (int p : nodePoints[limb.path[i]]) {
            const bool covered = std::any_of(others.begin(), others.end(), [&](int n) {
                return (points[p] - graph.nodes[n]).norm() <= reachOf[std::size_t(n)];
            });
            if (!covered && double(++outside) > allowedOutside) return false;
        }
    }
    return true;
}

namespace {

// One of a junction's other bones, as isCornerLimb reads it: its direction and median radius
// over up to kCornerArmBones bones from the junction.
struct Arm {
    Point direction = Point::Zero();  // zero when the bones end where they began
    double radius = 0.0;
};

Arm armFrom(const SkeletonGraph& graph, const std::vector<std::vector<int>>& neighbours, int junction, int next) {
    const std::vector<int> chain = walkChain(neighbours, junction, next);
    const std::size_t last = std::min(kCornerArmBones, chain.size() - 1);
    Arm arm;
    arm.direction = chainDirection(graph, chain, kCornerArmBones);
    std::vector<double> radii;
    for (std::size_t i = 1; i <= last; ++i) radii.push_back(graph.radii[std::size_t(chain[i])]);
    arm.radius = median(std::move(radii));
    return arm;
}

}  // namespace

bool isCornerLimb(const SkeletonGraph& graph, const Limb& limb, const PointList& points,
                  const std::vector<std::vector<int>>& nodePoints) {
    if (!limb.atJunction || graph.pointNode.size() != points.size() || limb.path.size() < 2) return false;
    const int junction = limb.path.back();
    const auto neighbours = adjacencyLists(graph.nodeCount(), graph.edges);
    if (neighbours[std::size_t(junction)].size() != 3) return false;
    std::vector<Arm> arms;
    for (int next : neighbours[std::size_t(junction)]) {
        if (next != limb.path[limb.path.size() - 2]) arms.push_back(armFrom(graph, neighbours, junction, next));
    }
    if (arms.size() != 2 || arms[0].direction.isZero() || arms[1].direction.isZero()) return false;
    const double bendCosine = arms[0].direction.dot(arms[1].direction);
    const Point inward = arms[0].direction + arms[1].direction;
    if (bendCosine < kCornerBendCosine || !(inward.norm() > 0.0)) return false;

    // The limb's points: where they lie (their centroid) and how far they reach.
    const Point& at = graph.nodes[std::size_t(junction)];
    std::vector<double> distances;
    std::vector<double> limbRadii;
    Point centroid = Point::Zero();
    for (std::size_t i = 0; i + 1 < limb.path.size(); ++i) {
        limbRadii.push_back(graph.radii[std::size_t(limb.path[i])]);
        for (int p : nodePoints[std::size_t(limb.path[i])]) {
            distances.push_back((points[std::size_t(p)] - at).norm());
            centroid += points[std::size_t(p)];
        }
    }
    if (distances.empty()) return false;
    const Point toLimb = centroid / double(distances.size()) - at;
    if (!(toLimb.norm() > 0.0) || -toLimb.normalized().dot(inward.normalized()) < kCornerAimCosine) return false;
    const double armRadius = std::min(arms[0].radius, arms[1].radius);
    if (median(std::move(limbRadii)) < kCornerThickness * armRadius) return false;
    const double halfBendSine = std::sqrt(0.5 * (1.0 - bendCosine));
    const double cornerReach = armRadius / std::max(halfBendSine, kCornerMinHalfBendSine);
    return quantile(std::move(distances), kCornerReachQuantile) <= kCornerSlack * cornerReach;
}

std::vector<std::vector<int>> shortCycleBasis(const SkeletonGraph& graph) {
    const auto neighbours = adjacencyLists(graph.nodeCount(), graph.edges);
    // A breadth-first spanning forest; every other bone closes one independent cycle.
    std::vector<int> parent(graph.nodeCount(), -2);
    for (std::size_t root = 0; root < graph.nodeCount(); ++root) {
        if (parent[root] != -2) continue;
        parent[root] = -1;
        std::queue<int> queue;
        queue.push(int(root));
        while (!queue.empty()) {
            const int n = queue.front();
            queue.pop();
            for (int m : neighbours[n]) {
                if (parent[m] == -2) parent[m] = n, queue.push(m);
            }
        }
    }
    std::vector<std::vector<int>> cycles;
    for (const Edge& e : graph.edges) {
        if (parent[e[0]] == e[1] || parent[e[1]] == e[0]) continue;
        std::vector<int> cycle = shortestDetour(graph, neighbours, e[0], e[1]);
        if (!cycle.empty()) cycles.push_back(std::move(cycle));
    }
    return cycles;
}

namespace {

// The coarsest sampling, in node radii (median distance between nearest points), on which
// a bone passing close to the surface tells a contact: libcgal-demo's eight of 315 mesh
// vertices (0.34 around its waist) keeps its two holes; the narrow loops cut on the
// robustness suite and the paper's inputs are sampled at 0.07-0.25.
constexpr double kCoarsestJudgedSpacing = 0.3;

struct CycleSize {
    double tube = 0.0;  // mean radius of its nodes
    double reach = 0.0; // mean distance of its nodes from their centroid
};

CycleSize measureCycle(const SkeletonGraph& graph, const std::vector<int>& cycle) {
    Point centre = Point::Zero();
    CycleSize size;
    for (int n : cycle) centre += graph.nodes[n], size.tube += graph.radii[n];
    centre /= double(cycle.size());
    size.tube /= double(cycle.size());
    for (int n : cycle) size.reach += (graph.nodes[n] - centre).norm();
    size.reach /= double(cycle.size());
    return size;
}

}  // namespace

bool isSpuriousCycle(const SkeletonGraph& graph, const std::vector<int>& cycle, double nodeSpacing) {
    const CycleSize size = measureCycle(graph, cycle);
    return size.reach < std::max(size.tube, nodeSpacing);
}

bool isNarrowCycle(const SkeletonGraph& graph, const std::vector<int>& cycle, double minOpening) {
    const CycleSize size = measureCycle(graph, cycle);
    return size.reach - size.tube < minOpening * size.tube;
}

bool boneGrazesSurface(const SkeletonGraph& graph, const Edge& bone, const PointList& points,
                       const std::vector<std::vector<int>>& nodePoints, double minClearance) {
    // The points near the bone are those of its ends and of their neighbours: where two
    // parts touch, the surface between them belongs to the nodes the bone joins.
    const auto neighbours = adjacencyLists(graph.nodeCount(), graph.edges);
    std::vector<int> nearbyNodes{bone[0], bone[1]};
    for (int end : bone) nearbyNodes.insert(nearbyNodes.end(), neighbours[end].begin(), neighbours[end].end());
    std::sort(nearbyNodes.begin(), nearbyNodes.end());
    nearbyNodes.erase(std::unique(nearbyNodes.begin(), nearbyNodes.end()), nearbyNodes.end());
    PointList nearby;
    for (int node : nearbyNodes) {
        for (int p : nodePoints[node]) nearby.push_back(points[p]);
    }
    if (nearby.size() < 2) return false;

    // On a coarsely sampled surface the bones cut corners and pass near the wall of a real
    // hole: no judgement there.
    const double radius = 0.5 * (graph.radii[bone[0]] + graph.radii[bone[1]]);
    const PointIndex index(nearby);
    std::vector<double> spacings;
    std::vector<int> found;
    const std::size_t stride = std::max<std::size_t>(1, nearby.size() / 200);
    for (std::size_t i = 0; i < nearby.size(); i += stride) {
        index.nearest(nearby[i], 2, found);
        spacings.push_back((nearby[std::size_t(found.back())] - nearby[i]).norm());
    }
    if (median(spacings) > kCoarsestJudgedSpacing * radius) return false;

    const Point& a = graph.nodes[bone[0]];
    const Point& b = graph.nodes[bone[1]];
    // The middle half: its ends sit inside their own tubes whatever the bone crosses.
    for (double t : {0.25, 0.375, 0.5, 0.625, 0.75}) {
        const Point x = a + t * (b - a);
        const double clearance = minClearance * ((1 - t) * graph.radii[bone[0]] + t * graph.radii[bone[1]]);
        index.withinRadius(x, clearance, found);
        if (!found.empty()) return true;
    }
    return false;
}

namespace {

// A node whose points spread in a plane (thickness across it under this share of their
// spread in it, as variances) stands on a sheet: a leaf, a plate. A tube's ring, even a
// half ring seen from one side (0.19), is twice as thick.
constexpr double kSheetFlatness = 0.1;
constexpr int kSheetMinimumPoints = 8;

bool isSheetNode(const PointList& points, const std::vector<int>& own) {
    if (own.size() < std::size_t(kSheetMinimumPoints)) return false;
    const Eigen::Vector3d spread = fitLocalPlane(points, own).variances;
    return spread(0) < kSheetFlatness * spread(1);
}

}  // namespace

std::vector<LoopToOpen> contactLoops(const SkeletonGraph& graph, const PointList& points,
                                      const RefinementLimits& limits) {
    std::vector<LoopToOpen> loops;
    if (points.empty() || !(limits.minOpening > 0.0)) return loops;
    const std::vector<std::vector<int>> nodePoints = pointsOfNodes(graph);
    for (std::vector<int>& cycle : shortCycleBasis(graph)) {
        if (!isNarrowCycle(graph, cycle, limits.minOpening)) continue;
        // Around a hole in a sheet every bone lies on the surface and the nodes' spread is
        // the sheet's, not a tube's: such a loop is the hole, not a contact.
        const auto sheetNodes = std::count_if(cycle.begin(), cycle.end(),
                                              [&](int n) { return isSheetNode(points, nodePoints[n]); });
        if (2 * sheetNodes > long(cycle.size())) continue;
        const Edge bone = mostStretchedBone(graph, cycle);
        if (boneGrazesSurface(graph, bone, points, nodePoints, limits.minClearance)) loops.push_back({std::move(cycle), bone});
    }
    return loops;
}

namespace {

// Whether `q` lies inside the closed polygon `corners` (even-odd rule).
bool insidePolygon(const std::vector<Eigen::Vector2d>& corners, const Eigen::Vector2d& q) {
    bool inside = false;
    for (std::size_t i = 0, j = corners.size() - 1; i < corners.size(); j = i++) {
        const Eigen::Vector2d& a = corners[i];
        const Eigen::Vector2d& b = corners[j];
        if ((a.y() > q.y()) != (b.y() > q.y()) && q.x() < a.x() + (b.x() - a.x()) * (q.y() - a.y()) / (b.y() - a.y())) {
            inside = !inside;
        }
    }
    return inside;
}

// At most this many disc centres are tried across a loop's extent, per side: a loop hundreds
// of steps wide is measured a little more coarsely rather than slowly.
constexpr int kMostDiscCentresPerSide = 150;
// filledLoops tries disc centres a quarter node spacing apart: each widest disc is found
// within a fifth of a node spacing, a small share of the limit.
constexpr double kDiscCentresPerNodeSpacing = 4.0;

// A loop as seen along its axis: its nodes projected on their best-fit plane.
struct LoopOutline {
    LocalPlane plane;
    std::vector<Eigen::Vector2d> corners;  // the loop's nodes in the plane, in order
    Eigen::Vector2d low, high;             // their bounding box

    LoopOutline(const SkeletonGraph& graph, const std::vector<int>& cycle)
        : plane(fitLocalPlane(graph.nodes, cycle)),
          low(Eigen::Vector2d::Constant(std::numeric_limits<double>::max())),
          high(-low) {
        for (int n : cycle) {
            corners.push_back(inPlane(graph.nodes[n]));
            low = low.cwiseMin(corners.back());
            high = high.cwiseMax(corners.back());
        }
    }
    Eigen::Vector2d inPlane(const Point& p) const {
        const Point d = p - plane.centroid;
        return Eigen::Vector2d(d.dot(plane.axes.col(2)), d.dot(plane.axes.col(1)));
    }
    double offPlane(const Point& p) const { return std::abs((p - plane.centroid).dot(plane.axes.col(0))); }
};

double emptyDiscRadius(const LoopOutline& outline, const std::vector<int>& cycle, const PointList& points,
                       const std::vector<std::vector<int>>& nodePoints, double step) {
    const double extent = (outline.high - outline.low).maxCoeff();
    if (!(extent > 0.0)) return 0.0;
    PointList projected;  // in the plane's coordinates, the third one 0 (PointIndex is 3-D)
    for (int n : cycle) {
        for (int p : nodePoints[n]) {
            const Eigen::Vector2d q = outline.inPlane(points[std::size_t(p)]);
            projected.push_back(Point(q.x(), q.y(), 0.0));
        }
    }
    if (projected.empty()) return extent;
    const PointIndex index(projected);
    step = std::max(step, extent / kMostDiscCentresPerSide);
    double widest = 0.0;
    std::vector<int> nearest;
    for (double x = outline.low.x() + 0.5 * step; x < outline.high.x(); x += step) {
        for (double y = outline.low.y() + 0.5 * step; y < outline.high.y(); y += step) {
            if (!insidePolygon(outline.corners, Eigen::Vector2d(x, y))) continue;
            const Point centre(x, y, 0.0);
            index.nearest(centre, 1, nearest);
            widest = std::max(widest, (projected[std::size_t(nearest.front())] - centre).norm());
        }
    }
    return widest;
}

// A limb lies across a loop when at least this many of its nodes do, a bone's length: a
// single node there is more often the end of a spur that outliers grew (libcgal-demo's eight
// with 5% outliers has one over a hole).
constexpr int kFewestNodesAcross = 2;

// Whether nodes of the loop's own part, on no loop, lie over its hole: inside its outline
// and off its plane by more than the loop's mean radius (so not the loop's own tube). Such
// nodes are on a limb: a limb in front of a body seen from one view hides the body behind
// it, and contraction rings that shadow as if it were a hole. (Nodes of other loops do not
// count: a knot's strands cross over each other's loops.)
bool partAcrossLoop(const SkeletonGraph& graph, const std::vector<int>& cycle, const LoopOutline& outline,
                    const std::vector<int>& partOf, const std::vector<char>& onLoops) {
    double meanRadius = 0.0;
    for (int n : cycle) meanRadius += graph.radii[n];
    meanRadius /= double(cycle.size());
    int across = 0;
    for (int n = 0; n < int(graph.nodeCount()) && across < kFewestNodesAcross; ++n) {
        if (onLoops[n] || partOf[n] != partOf[cycle.front()]) continue;
        across += outline.offPlane(graph.nodes[n]) > meanRadius &&
                  insidePolygon(outline.corners, outline.inPlane(graph.nodes[n]));
    }
    return across >= kFewestNodesAcross;
}

// The connected part of each node, as the representative of its set.
std::vector<int> partsOfNodes(const SkeletonGraph& graph) {
    DisjointSets parts(graph.nodeCount());
    for (const Edge& e : graph.edges) parts.unite(e[0], e[1]);
    std::vector<int> partOf(graph.nodeCount());
    for (int n = 0; n < int(graph.nodeCount()); ++n) partOf[n] = parts.find(n);
    return partOf;
}

// Whether each node is on one of `loops`.
std::vector<char> nodesOnLoops(std::size_t nodeCount, const std::vector<std::vector<int>>& loops) {
    std::vector<char> on(nodeCount, 0);
    for (const std::vector<int>& loop : loops) {
        for (int n : loop) on[n] = 1;
    }
    return on;
}

}  // namespace

double emptyDiscRadius(const SkeletonGraph& graph, const std::vector<int>& cycle, const PointList& points,
                       const std::vector<std::vector<int>>& nodePoints, double step) {
    return emptyDiscRadius(LoopOutline(graph, cycle), cycle, points, nodePoints, step);
}

bool partAcrossLoop(const SkeletonGraph& graph, const std::vector<int>& cycle) {
    return partAcrossLoop(graph, cycle, LoopOutline(graph, cycle), partsOfNodes(graph),
                          nodesOnLoops(graph.nodeCount(), shortCycleBasis(graph)));
}

std::vector<LoopToOpen> filledLoops(const SkeletonGraph& graph, const PointList& points, double nodeSpacing,
                                     const RefinementLimits& limits) {
    std::vector<LoopToOpen> loops;
    if (points.empty() || !(limits.minHole > 0.0)) return loops;
    const std::vector<std::vector<int>> nodePoints = pointsOfNodes(graph);
    const std::vector<int> partOf = partsOfNodes(graph);
    std::vector<std::vector<int>> basis = shortCycleBasis(graph);
    const std::vector<char> onLoops = nodesOnLoops(graph.nodeCount(), basis);
    for (std::vector<int>& cycle : basis) {
        const LoopOutline outline(graph, cycle);
        const double hole =
            emptyDiscRadius(outline, cycle, points, nodePoints, nodeSpacing / kDiscCentresPerNodeSpacing);
        if (hole >= limits.minHole * nodeSpacing && !partAcrossLoop(graph, cycle, outline, partOf, onLoops)) {
            continue;
        }
        const Edge bone = mostStretchedBone(graph, cycle);
        loops.push_back({std::move(cycle), bone});
    }
    return loops;
}

Edge mostStretchedBone(const SkeletonGraph& graph, const std::vector<int>& cycle) {
    Edge best{cycle[0], cycle[1 % cycle.size()]};
    double bestStretch = -1.0;
    for (std::size_t i = 0; i < cycle.size(); ++i) {
        const int a = cycle[i], b = cycle[(i + 1) % cycle.size()];
        const double reach = graph.radii[a] + graph.radii[b];
        const double stretch = (graph.nodes[a] - graph.nodes[b]).norm() / std::max(reach, 1e-300);
        if (stretch > bestStretch) bestStretch = stretch, best = edgeBetween(a, b);
    }
    return best;
}

std::vector<std::vector<int>> closeJunctionPaths(const SkeletonGraph& graph, double nodeSpacing) {
    std::vector<std::vector<int>> paths;
    for (std::vector<int>& path : junctionToJunctionPaths(adjacencyLists(graph.nodeCount(), graph.edges))) {
        if (pathLength(graph, path) < nodeSpacing) paths.push_back(std::move(path));
    }
    return paths;
}

}  // namespace pcskeleton
