#include "pcskeleton/skeleton/skeleton_branches.h"

#include "pcskeleton/core/errors.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <set>
#include <string>

namespace pcskeleton {

namespace {

// Each part's root: its lowest node along `up` (the lowest index among equals), or
// `chosen` for the part holding it.
std::vector<int> partRoots(const std::vector<std::vector<int>>& neighbours, const PointList& nodes, const Point& up,
                           int chosen) {
    std::vector<int> part(nodes.size(), -1), roots;
    for (std::size_t start = 0; start < nodes.size(); ++start) {
        if (part[start] >= 0) continue;
        const int id = int(roots.size());
        int lowest = int(start);
        std::vector<int> stack{int(start)};
        part[start] = id;
        while (!stack.empty()) {
            const int n = stack.back();
            stack.pop_back();
            if (nodes[n].dot(up) < nodes[lowest].dot(up)) lowest = n;
            for (int m : neighbours[n]) {
                if (part[m] < 0) part[m] = id, stack.push_back(m);
            }
        }
        roots.push_back(lowest);
    }
    if (chosen >= 0) roots[part[chosen]] = chosen;
    return roots;
}

double angleDegrees(const Point& a, const Point& b) {
    if (!(a.norm() > 0.0) || !(b.norm() > 0.0)) return std::numeric_limits<double>::quiet_NaN();
    return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180.0 / M_PI;
}

void measureShape(const SkeletonGraph& skeleton, Branch& branch) {
    const std::vector<int>& path = branch.nodes;
    const auto radius = [&](int n) { return skeleton.radii[std::size_t(n)]; };
    double radiusLength = 0.0;
    for (std::size_t i = 1; i < path.size(); ++i) {
        const double h = (skeleton.nodes[path[i]] - skeleton.nodes[path[i - 1]]).norm();
        const double a = radius(path[i - 1]), b = radius(path[i]);
        branch.length += h;
        radiusLength += h * (a + b) / 2.0;
        branch.volume += M_PI * h / 3.0 * (a * a + a * b + b * b);
    }
    branch.chord = (skeleton.nodes[path.back()] - skeleton.nodes[path.front()]).norm();
    branch.baseRadius = radius(path.front());
    branch.tipRadius = radius(path.back());
    branch.meanRadius = branch.length > 0.0 ? radiusLength / branch.length : branch.baseRadius;
}

// The node halfway along a branch (by length).
int halfwayNode(const SkeletonGraph& skeleton, const Branch& branch) {
    double along = 0.0;
    for (std::size_t i = 1; i < branch.nodes.size(); ++i) {
        along += (skeleton.nodes[branch.nodes[i]] - skeleton.nodes[branch.nodes[i - 1]]).norm();
        if (along >= branch.length / 2.0) return branch.nodes[i];
    }
    return branch.nodes.back();
}

// The direction a branch leaves its base, and the one it has at its tip, each over half
// its length: the nodes next to a junction lean towards it, so a bone or two there tells
// little.
Point startDirection(const SkeletonGraph& skeleton, const Branch& branch) {
    return skeleton.nodes[halfwayNode(skeleton, branch)] - skeleton.nodes[branch.nodes.front()];
}
Point endDirection(const SkeletonGraph& skeleton, const Branch& branch) {
    return skeleton.nodes[branch.nodes.back()] - skeleton.nodes[halfwayNode(skeleton, branch)];
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

}  // namespace

SkeletonBranches measureBranches(const SkeletonGraph& skeleton, const BranchOptions& options) {
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
    SkeletonBranches result;
    std::vector<Branch>& branches = result.branches;
    result.nodeBranch.assign(count, -1);
    std::vector<double> nodePosition(count, 0.0);  // along the node's branch, input units
    std::vector<bool> reached(count, false);
    std::set<Edge> walked;
    const auto walk = [&](int a, int b) { return walked.insert(Edge{std::min(a, b), std::max(a, b)}).second; };

    for (int root : partRoots(neighbours, skeleton.nodes, options.up, options.root)) {
        if (neighbours[root].empty()) continue;  // an isolated node has no branch
        reached[root] = true;
        const std::size_t first = branches.size();
        std::deque<std::pair<int, int>> junctions{{root, -1}};  // (node, the branch reaching it)
        while (!junctions.empty()) {
            const auto [base, parent] = junctions.front();
            junctions.pop_front();
            for (int next : neighbours[base]) {
                if (!walk(base, next)) continue;
                Branch branch;
                branch.parent = parent;
                branch.nodes = {base};
                int previous = base, current = next;
                while (true) {
                    branch.nodes.push_back(current);
                    if (reached[current]) {
                        branch.closesLoop = true;
                        break;
                    }
                    reached[current] = true;
                    if (neighbours[current].size() != 2) break;
                    const int ahead = neighbours[current][0] == previous ? neighbours[current][1] : neighbours[current][0];
                    if (!walk(current, ahead)) break;
                    previous = current, current = ahead;
                }
                measureShape(skeleton, branch);
                const int index = int(branches.size());
                double along = 0.0;
                for (std::size_t i = 1; i < branch.nodes.size(); ++i) {
                    const int n = branch.nodes[i];
                    along += (skeleton.nodes[n] - skeleton.nodes[branch.nodes[i - 1]]).norm();
                    if (result.nodeBranch[n] < 0) result.nodeBranch[n] = index, nodePosition[n] = along;
                }
                if (!branch.closesLoop && neighbours[branch.nodes.back()].size() >= 3) {
                    junctions.push_back({branch.nodes.back(), index});
                }
                branch.angleToParent = parent < 0 ? std::numeric_limits<double>::quiet_NaN()
                                                  : angleDegrees(endDirection(skeleton, branches[parent]),
                                                                 startDirection(skeleton, branch));
                branches.push_back(std::move(branch));
            }
        }
        if (branches.size() > first && result.nodeBranch[root] < 0) result.nodeBranch[root] = int(first);
    }
    assignOrders(branches);

    result.pointBranch.assign(skeleton.pointNode.size(), -1);
    result.pointPosition.assign(skeleton.pointNode.size(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t i = 0; i < skeleton.pointNode.size(); ++i) {
        const int node = skeleton.pointNode[i];
        if (node < 0 || node >= int(count) || result.nodeBranch[node] < 0) continue;
        Branch& branch = branches[std::size_t(result.nodeBranch[node])];
        result.pointBranch[i] = result.nodeBranch[node];
        result.pointPosition[i] = branch.length > 0.0 ? nodePosition[node] / branch.length : 0.0;
        ++branch.points;
    }
    return result;
}

}  // namespace pcskeleton
