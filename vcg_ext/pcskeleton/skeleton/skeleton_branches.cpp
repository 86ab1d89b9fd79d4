#include "pcskeleton/skeleton/skeleton_branches.h"

#include "pcskeleton/core/errors.h"
#include "pcskeleton/internal/disjoint_sets.h"
#include "pcskeleton/internal/local_plane.h"
#include "pcskeleton/skeleton/skeleton_structure.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <set>
#include <string>

namespace pcskeleton {

namespace {

// Each part's root: its lowest node along `up` (the lowest index among equals), or
// `chosen` for the part holding it; parts in the order of their lowest-numbered node.
std::vector<int> partRoots(const SkeletonGraph& skeleton, const Point& up, int chosen) {
    DisjointSets parts(skeleton.nodeCount());
    for (const Edge& e : skeleton.edges) parts.unite(e[0], e[1]);
    std::vector<int> rootOf(skeleton.nodeCount(), -1), order;  // by each part's representative
    for (std::size_t n = 0; n < skeleton.nodeCount(); ++n) {
        int& root = rootOf[std::size_t(parts.find(int(n)))];
        if (root < 0) order.push_back(parts.find(int(n)));
        if (root < 0 || skeleton.nodes[n].dot(up) < skeleton.nodes[std::size_t(root)].dot(up)) root = int(n);
    }
    if (chosen >= 0) rootOf[std::size_t(parts.find(chosen))] = chosen;
    std::vector<int> roots;
    for (int part : order) roots.push_back(rootOf[std::size_t(part)]);
    return roots;
}

double angleDegrees(const Point& a, const Point& b) {
    if (!(a.norm() > 0.0) || !(b.norm() > 0.0)) return std::numeric_limits<double>::quiet_NaN();
    return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180.0 / M_PI;
}

// Junctions joined by a chain of bones whose fork points lie closer than their two radii
// together (their spheres overlap) are one junction, their arms leaving one knot:
// contraction splits a junction of four or more arms into two or three such. The chains
// that join a knot's junctions, its inner bones, are a tree: where junctions are joined
// already (by shorter chains), a further chain between them is a loop of the skeleton, a
// handle or a hole, and stays a branch. `group` gives each node of a group (its junctions
// and the nodes of its inner bones) the group's number, -1 to every other node.
struct JunctionGroups {
    std::vector<int> group;             // per node
    std::vector<std::vector<int>> junctions;  // per group
    std::set<Edge> innerBones;          // every bone of the inner chains

    bool isInnerBone(const std::vector<int>& chain) const {
        return chain.size() >= 2 && innerBones.count(edgeBetween(chain[0], chain[1])) > 0;
    }
};

// Where on the segment from `a` to `b` the point nearest `p` lies, from 0 (at a) to 1 (at b).
double nearestOnSegment(const Point& p, const Point& a, const Point& b) {
    const Point ab = b - a;
    return ab.squaredNorm() > 0.0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
}

// Whether `p` lies within the tubes about a junction (or a knot of junctions): the ball of
// one of its junctions, or the radius (interpolated) about one of `bones`.
bool withinTubes(const SkeletonGraph& skeleton, const std::vector<int>& junctions, const std::vector<Edge>& bones,
                 const Point& p) {
    for (int junction : junctions) {
        if ((p - skeleton.nodes[std::size_t(junction)]).norm() <= skeleton.radii[std::size_t(junction)]) return true;
    }
    for (const Edge& e : bones) {
        const Point &a = skeleton.nodes[e[0]], &b = skeleton.nodes[e[1]];
        const double t = nearestOnSegment(p, a, b);
        if ((p - ((1.0 - t) * a + t * b)).norm() <= (1.0 - t) * skeleton.radii[e[0]] + t * skeleton.radii[e[1]]) return true;
    }
    return false;
}

// How far `p` lies from the line through `fit`'s centroid along its axis.
double distanceFromLine(const Point& p, const LocalPlane& fit) {
    const Point direction = fit.axes.col(2), offset = p - fit.centroid;
    return (offset - offset.dot(direction) * direction).norm();
}

// Adds to `line` (an arm's nodes for its line, at least two) the arm's nodes from `next` on,
// one at a time, while each lies within kStraightArm junction radii of the line fitted to
// those before it, and up to the arm's other end (a junction's node is not the arm's own).
// Under noise a line fitted along more of the arm tilts less; a bend ends it.
void extendWhileStraight(const SkeletonGraph& skeleton, const std::vector<std::vector<int>>& neighbours,
                         const std::vector<int>& arm, std::size_t next, double radius, std::vector<int>& line) {
    // Wide enough for the scatter of a noisy straight arm's nodes, narrow enough that a bend
    // ends the line. Chosen on the Y and the star (docs/benchmarks.md#branch-measures).
    constexpr double kStraightArm = 0.5;
    for (; next < arm.size() && neighbours[std::size_t(arm[next])].size() < 3; ++next) {
        const Point& node = skeleton.nodes[std::size_t(arm[next])];
        if (distanceFromLine(node, fitLocalPlane(skeleton.nodes, line)) > kStraightArm * radius) return;
        line.push_back(arm[next]);
    }
}

// Where a junction's arms meet: the point nearest (least squares) to the lines along its
// arms (for a group of junctions, the arms of all of them). Contraction leaves a junction's
// node in the middle of the arms' overlap, beyond the fork, so that measured from it the
// stem is too long and the arms too short (docs/benchmarks.md#branch-measures). Each arm's
// line is fitted to its nodes from one junction radius away (nearer ones lean towards the
// junction) out to kArmLineReach radii, and on as long as the arm stays straight
// (extendWhileStraight). The junction's node itself when fewer than two arms give a line,
// or when that point lies outside the tubes the lines were fitted in (withinTubes): the
// junctions', those of the bones between a knot's junctions and of the arms' bones out to
// the lines' reach. Where arms part at a small angle their tubes overlap far beyond the
// fork, and contraction leaves the junction's node there, more than its radius from the
// fork, which then lies in the parent's tube.
Point forkPoint(const SkeletonGraph& skeleton, const std::vector<std::vector<int>>& neighbours,
                const JunctionGroups& groups, const std::vector<int>& junctions) {
    const Point& node = skeleton.nodes[std::size_t(junctions.front())];
    constexpr double kPull = 1e-3;  // towards the node, so that parallel arms still give one point
    // Out to this the line takes every node of the arm; beyond, only while the arm is straight.
    // Farther, a bent arm's line misses the fork; nearer, a noisy arm's wavers. Chosen on the Y
    // and the star over ten samples each (docs/benchmarks.md#branch-measures).
    constexpr double kArmLineReach = 5.0;
    Eigen::Matrix3d normal = kPull * Eigen::Matrix3d::Identity();
    Point right = kPull * node;
    int lines = 0;
    std::vector<Edge> tubeBones;  // the knot's inner bones and the arms' bones out to the lines' reach
    for (int junction : junctions) {
        const double radius = skeleton.radii[std::size_t(junction)];
        for (int next : neighbours[std::size_t(junction)]) {
            const std::vector<int> arm = walkChain(neighbours, junction, next);
            const bool inner = groups.isInnerBone(arm);
            std::vector<int> far;
            double along = 0.0;
            std::size_t beyondReach = arm.size();  // the first node past the reach
            for (std::size_t i = 1; i < arm.size() && (inner || along <= kArmLineReach * radius); ++i) {
                along += (skeleton.nodes[std::size_t(arm[i])] - skeleton.nodes[std::size_t(arm[i - 1])]).norm();
                tubeBones.push_back({arm[i - 1], arm[i]});
                if (!inner && along >= radius && along <= kArmLineReach * radius) far.push_back(arm[i]);
                if (along > kArmLineReach * radius) beyondReach = std::min(beyondReach, i);
            }
            if (inner) continue;
            if (far.size() < 2) continue;
            extendWhileStraight(skeleton, neighbours, arm, beyondReach, radius, far);
            const LocalPlane fit = fitLocalPlane(skeleton.nodes, far);
            const Point direction = fit.axes.col(2);
            const Eigen::Matrix3d across = Eigen::Matrix3d::Identity() - direction * direction.transpose();
            normal += across;
            right += across * fit.centroid;
            ++lines;
        }
    }
    if (lines < 2) return node;
    const Point fork = normal.ldlt().solve(right);
    if (!fork.allFinite()) return node;
    return withinTubes(skeleton, junctions, tubeBones, fork) ? fork : node;
}

JunctionGroups groupJunctions(const SkeletonGraph& skeleton, const std::vector<std::vector<int>>& neighbours) {
    const std::size_t count = skeleton.nodeCount();
    // Each junction's own fork point: the nodes of a split junction scatter more than the
    // fork points of its parts.
    JunctionGroups none;
    none.group.assign(count, -1);
    std::vector<Point> fork(count);
    for (std::size_t a = 0; a < count; ++a) {
        if (neighbours[a].size() >= 3) fork[a] = forkPoint(skeleton, neighbours, none, {int(a)});
    }
    // Each chain that could join two junctions into a knot, shortest first. Each is found
    // from both its ends; the second time, its junctions are joined already.
    struct Candidate {
        double length;
        std::vector<int> chain;
    };
    std::vector<Candidate> candidates;
    std::vector<bool> inKnot(count, false);
    for (std::size_t a = 0; a < count; ++a) {
        if (neighbours[a].size() < 3) continue;
        inKnot[a] = true;
        for (int next : neighbours[a]) {
            std::vector<int> chain = walkChain(neighbours, int(a), next);
            const std::size_t b = std::size_t(chain.back());
            if (b == a || neighbours[b].size() < 3) continue;
            if ((fork[a] - fork[b]).norm() >= skeleton.radii[a] + skeleton.radii[b]) continue;
            const double length = pathLength(skeleton, chain);
            candidates.push_back({length, std::move(chain)});
        }
    }
    std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) { return x.length < y.length; });
    DisjointSets knots(count);
    JunctionGroups groups;
    for (const Candidate& candidate : candidates) {
        const std::vector<int>& chain = candidate.chain;
        if (knots.find(chain.front()) == knots.find(chain.back())) continue;  // a loop: a branch
        for (int n : chain) knots.unite(chain.front(), n), inKnot[std::size_t(n)] = true;
        for (std::size_t i = 1; i < chain.size(); ++i) groups.innerBones.insert(edgeBetween(chain[i - 1], chain[i]));
    }
    groups.group.assign(count, -1);
    std::vector<int> numberOf(count, -1);
    for (std::size_t n = 0; n < count; ++n) {
        if (!inKnot[n]) continue;
        int& number = numberOf[std::size_t(knots.find(int(n)))];
        if (number < 0) number = int(groups.junctions.size()), groups.junctions.emplace_back();
        groups.group[n] = number;
        if (neighbours[n].size() >= 3) groups.junctions[std::size_t(number)].push_back(int(n));
    }
    return groups;
}

// Moves the nodes at the front of `course` that lie behind its first point, a fork point
// `behind` away from its junction's node, onto it: those nearer to the fork point than the
// node is, while the next node lies nearer still (they are not on the way from there along
// the branch). Contraction leaves a junction's node beyond the fork, in the arms' overlap,
// and the nodes there would take the course out past the fork and back. Moves none from
// `last` on; returns the index of the last node at the first point.
std::size_t gatherBehindStart(std::vector<Point>& course, double behind, std::size_t last) {
    const Point start = course.front();
    const auto distance = [&](std::size_t i) { return (course[i] - start).norm(); };
    std::size_t i = 1;
    for (; i < last && distance(i) < behind && distance(i + 1) < distance(i); ++i) course[i] = start;
    return i - 1;
}

// The course a branch is measured along: its nodes, a junction at either end at its fork
// point with the nodes behind it (gatherBehindStart), the others smoothed. The nodes scatter
// a little across the bone, and a zigzag is longer than the bone, the more so with noise.
// Taubin's smoothing (a step in, then a slightly larger step out) takes the zigzag out and
// leaves bends as they are: a wave of k node spacings keeps (1 - 0.5 c)(1 + 0.53 c) of
// itself per round, c = 1 - cos(2 pi / k): nothing of a zigzag (k = 2) stays, and nearly all
// of a wave many spacings long. The nodes at a fork point stay there: the step out would
// push them past it.
std::vector<Point> courseOf(const SkeletonGraph& skeleton, const std::vector<Point>& forks, const std::vector<int>& nodes) {
    std::vector<Point> course;
    for (int n : nodes) course.push_back(forks[std::size_t(n)]);
    const auto behind = [&](int n) { return (skeleton.nodes[std::size_t(n)] - forks[std::size_t(n)]).norm(); };
    const std::size_t end = course.size() - 1;
    std::size_t from = 0, to = end;  // the last node at the base's fork point, the first at the tip's
    // Each end takes nodes from its own half only: a loop's course ends where it starts.
    if (course.size() > 2) {
        from = gatherBehindStart(course, behind(nodes.front()), end / 2);
        std::reverse(course.begin(), course.end());
        to = end - gatherBehindStart(course, behind(nodes.back()), end - end / 2);
        std::reverse(course.begin(), course.end());
    }
    for (int round = 0; round < 2; ++round) {
        for (double step : {0.5, -0.53}) {
            std::vector<Point> moved = course;
            for (std::size_t i = from + 1; i < to; ++i) {
                moved[i] = course[i] + step * (0.5 * (course[i - 1] + course[i + 1]) - course[i]);
            }
            course = std::move(moved);
        }
    }
    return course;
}

// The length of each bone of a course: bones[i] joins course[i - 1] and course[i] (bones[0] = 0).
std::vector<double> boneLengths(const std::vector<Point>& course) {
    std::vector<double> bones(course.size(), 0.0);
    for (std::size_t i = 1; i < course.size(); ++i) bones[i] = (course[i] - course[i - 1]).norm();
    return bones;
}

// The radius of a branch at each of its nodes. A junction's node holds points of all its
// arms, and their mean distance measures the knot's spread, not a tube: at a junction (of
// a knot) the branch has the radius of its nearest node outside it.
std::vector<double> branchRadii(const SkeletonGraph& skeleton, const JunctionGroups& groups, const std::vector<int>& path) {
    std::vector<double> radii;
    for (int n : path) radii.push_back(skeleton.radii[std::size_t(n)]);
    const auto outside = [&](int n) { return groups.group[std::size_t(n)] < 0; };
    const auto first = std::find_if(path.begin(), path.end(), outside);
    if (first == path.end()) return radii;
    const auto last = std::find_if(path.rbegin(), path.rend(), outside);
    for (std::size_t i = 0; i < path.size(); ++i) {
        if (outside(path[i])) continue;
        const bool nearerTheBase = i < path.size() / 2;
        radii[i] = skeleton.radii[std::size_t(nearerTheBase ? *first : *last)];
    }
    return radii;
}

void measureShape(const std::vector<double>& radii, const std::vector<Point>& course, const std::vector<double>& bones,
                  Branch& branch) {
    const std::vector<int>& path = branch.nodes;
    double radiusLength = 0.0;
    branch.along.assign(1, 0.0);
    for (std::size_t i = 1; i < path.size(); ++i) {
        const double h = bones[i];
        const double a = radii[i - 1], b = radii[i];
        branch.along.push_back(branch.along.back() + h);
        radiusLength += h * (a + b) / 2.0;
        branch.volume += M_PI * h / 3.0 * (a * a + a * b + b * b);
    }
    branch.length = branch.along.back();
    branch.chord = (course.back() - course.front()).norm();
    branch.radii = radii;
    branch.baseRadius = radii.front();
    branch.tipRadius = radii.back();
    branch.meanRadius = branch.length > 0.0 ? radiusLength / branch.length : branch.baseRadius;
}

// The node halfway along a branch (by length), from each node's distance from its base.
std::size_t halfway(const std::vector<double>& along) {
    const auto middle = std::lower_bound(along.begin() + 1, along.end(), along.back() / 2.0);
    return std::min(std::size_t(middle - along.begin()), along.size() - 1);
}

// At each junction the main axis goes on into the child with the longest continuation (the
// lower-numbered among equals).
void assignOrders(std::vector<Branch>& branches) {
    // Children come after their parent (branches are found outwards from the root), so each
    // branch's continuation is known before its parent's.
    std::vector<double> bestChild(branches.size(), 0.0);
    std::vector<int> longestChild(branches.size(), -1);
    for (std::size_t b = branches.size(); b-- > 0;) {
        const double continuation = branches[b].length + bestChild[b];
        const int parent = branches[b].parent;
        if (parent >= 0 && (longestChild[parent] < 0 || continuation >= bestChild[parent])) {
            bestChild[parent] = continuation;
            longestChild[parent] = int(b);
        }
    }
    for (std::size_t b = 0; b < branches.size(); ++b) {
        const int parent = branches[b].parent;
        if (parent >= 0) branches[b].order = branches[parent].order + (longestChild[parent] == int(b) ? 0 : 1);
    }
}

// The point of a branch's course nearest `p` among its bones within `bones` of the end at
// `atBase` (its base) or not (its tip): (distance, place along the branch).
std::pair<double, double> nearestOnCourseEnd(const std::vector<Point>& course, const std::vector<double>& along,
                                             bool atBase, std::size_t bones, const Point& p) {
    std::pair<double, double> best{std::numeric_limits<double>::infinity(), 0.0};
    const std::size_t last = course.size() - 1;
    for (std::size_t k = 0; k < std::min(bones, last); ++k) {
        const std::size_t i = atBase ? k : last - k - 1;  // the bone from course[i] to course[i + 1]
        const double t = nearestOnSegment(p, course[i], course[i + 1]);
        const double distance = (p - ((1.0 - t) * course[i] + t * course[i + 1])).norm();
        if (distance < best.first) best = {distance, along[i] + t * (along[i + 1] - along[i])};
    }
    return best;
}

SkeletonBranches measureBranchesOf(const SkeletonGraph& skeleton, const PointList* points, const BranchOptions& options) {
    const std::size_t count = skeleton.nodeCount();
    if (!options.up.allFinite() || !(options.up.norm() > 0.0)) {
        throw InvalidInput("The up axis has no length: give a direction such as 0 0 1.");
    }
    if (options.root < -1 || options.root >= int(count)) {
        throw InvalidInput("The root " + std::to_string(options.root) + " is not a node of the skeleton (it has " +
                           std::to_string(count) + " nodes, numbered from 0).");
    }
    if (skeleton.radii.size() != count) throw CallerError("measureBranches: one radius per node expected");

    const std::vector<std::vector<int>> neighbours = adjacencyLists(count, skeleton.edges);
    const JunctionGroups groups = groupJunctions(skeleton, neighbours);
    std::vector<Point> forks = skeleton.nodes;  // each node's place; a junction group's at its fork point
    std::vector<Point> groupFork;
    for (const std::vector<int>& junctions : groups.junctions) groupFork.push_back(forkPoint(skeleton, neighbours, groups, junctions));
    for (std::size_t n = 0; n < count; ++n) {
        if (groups.group[n] >= 0) forks[n] = groupFork[std::size_t(groups.group[n])];
    }
    // Per branch, the direction it has at its tip, over the half of it that ends there: the
    // nodes next to a junction lean towards it, so a bone or two there tells little. Its
    // children's angles are measured from it, to their own directions over their first half.
    std::vector<Point> endDirections;
    std::vector<std::vector<Point>> courses;  // per branch
    SkeletonBranches result;
    std::vector<Branch>& branches = result.branches;
    result.nodeBranch.assign(count, -1);
    std::vector<double> nodePosition(count, 0.0);  // along the node's branch, input units
    std::vector<bool> reached(count, false);
    // A knot of junctions is one place: reaching one of its junctions reaches them all, and a
    // branch that comes back to any of them closes a loop.
    const auto reach = [&](int n) {
        reached[std::size_t(n)] = true;
        const int knot = groups.group[std::size_t(n)];
        if (knot >= 0) {
            for (int junction : groups.junctions[std::size_t(knot)]) reached[std::size_t(junction)] = true;
        }
    };
    std::set<Edge> walked;
    const auto walk = [&](int a, int b) { return walked.insert(edgeBetween(a, b)).second; };

    int part = 0;
    for (int root : partRoots(skeleton, options.up, options.root)) {
        if (neighbours[root].empty()) continue;  // an isolated node has no branch
        reach(root);
        const std::size_t first = branches.size();
        std::deque<std::pair<int, int>> junctions{{root, -1}};  // (node, the branch reaching it)
        while (!junctions.empty()) {
            const auto [base, parent] = junctions.front();
            junctions.pop_front();
            for (int next : neighbours[base]) {
                // A chain's bones are walked together, so one walked bone means all are.
                if (!walk(base, next)) continue;
                Branch branch;
                branch.parent = parent;
                branch.part = part;
                branch.nodes = walkChain(neighbours, base, next);
                for (std::size_t i = 2; i < branch.nodes.size(); ++i) walk(branch.nodes[i - 1], branch.nodes[i]);
                if (groups.isInnerBone(branch.nodes)) {
                    // Inside one knot of junctions: no branch; the arms of its far junction
                    // leave the knot as those of this one do, from the same parent (also when
                    // a loop reached that junction first: its arms are walked from here).
                    for (std::size_t i = 1; i < branch.nodes.size(); ++i) {
                        const int n = branch.nodes[i];
                        reach(n);
                        if (parent >= 0 && result.nodeBranch[n] < 0) result.nodeBranch[n] = parent, nodePosition[n] = branches[parent].length;
                    }
                    junctions.push_front({branch.nodes.back(), parent});
                    continue;
                }
                branch.closesLoop = reached[branch.nodes.back()];
                courses.push_back(courseOf(skeleton, forks, branch.nodes));
                const std::vector<Point>& course = courses.back();
                const std::vector<double> bones = boneLengths(course);
                measureShape(branchRadii(skeleton, groups, branch.nodes), course, bones, branch);
                const Point middle = course[halfway(branch.along)];
                endDirections.push_back(course.back() - middle);
                const int index = int(branches.size());
                for (std::size_t i = 1; i < branch.nodes.size(); ++i) {
                    const int n = branch.nodes[i];
                    reach(n);
                    if (result.nodeBranch[n] < 0) result.nodeBranch[n] = index, nodePosition[n] = branch.along[i];
                }
                if (!branch.closesLoop && neighbours[branch.nodes.back()].size() >= 3) {
                    junctions.push_back({branch.nodes.back(), index});
                }
                branch.angleToParent = parent < 0 ? std::numeric_limits<double>::quiet_NaN()
                                                  : angleDegrees(endDirections[std::size_t(parent)], middle - course.front());
                branches.push_back(std::move(branch));
            }
        }
        if (branches.size() > first && result.nodeBranch[root] < 0) result.nodeBranch[root] = int(first);
        ++part;
    }
    assignOrders(branches);

    result.pointBranch.assign(skeleton.pointNode.size(), -1);
    result.pointPosition.assign(skeleton.pointNode.size(), std::numeric_limits<double>::quiet_NaN());
    // Per knot of junctions, the branches with an end there: (branch, whether at its base).
    std::vector<std::vector<std::pair<int, bool>>> knotBranches(groups.junctions.size());
    for (std::size_t b = 0; b < branches.size(); ++b) {
        const int base = groups.group[std::size_t(branches[b].nodes.front())];
        const int tip = groups.group[std::size_t(branches[b].nodes.back())];
        if (base >= 0) knotBranches[std::size_t(base)].push_back({int(b), true});
        if (tip >= 0) knotBranches[std::size_t(tip)].push_back({int(b), false});
    }
    // Near a knot a point is judged by the bones that leave it: farther, they lean apart.
    constexpr std::size_t kKnotBones = 3;
    for (std::size_t i = 0; i < skeleton.pointNode.size(); ++i) {
        const int node = skeleton.pointNode[i];
        if (node < 0 || node >= int(count) || result.nodeBranch[node] < 0) continue;
        int b = result.nodeBranch[node];
        double position = nodePosition[node];
        const int knot = groups.group[std::size_t(node)];
        if (points && knot >= 0) {
            double nearest = std::numeric_limits<double>::infinity();
            for (const auto& [candidate, atBase] : knotBranches[std::size_t(knot)]) {
                const auto [distance, along] = nearestOnCourseEnd(courses[std::size_t(candidate)], branches[std::size_t(candidate)].along,
                                                                  atBase, kKnotBones, (*points)[i]);
                if (distance < nearest) nearest = distance, b = candidate, position = along;
            }
        }
        Branch& branch = branches[std::size_t(b)];
        result.pointBranch[i] = b;
        result.pointPosition[i] = branch.length > 0.0 ? position / branch.length : 0.0;
        ++branch.points;
    }
    return result;
}

}  // namespace

SkeletonBranches measureBranches(const SkeletonGraph& skeleton, const BranchOptions& options) {
    return measureBranchesOf(skeleton, nullptr, options);
}

SkeletonBranches measureBranches(const SkeletonGraph& skeleton, const PointList& points, const BranchOptions& options) {
    if (points.size() != skeleton.pointNode.size()) {
        throw CallerError("measureBranches: one point per entry of the skeleton's correspondence expected");
    }
    return measureBranchesOf(skeleton, &points, options);
}

}  // namespace pcskeleton
