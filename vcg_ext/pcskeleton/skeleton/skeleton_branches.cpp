#include "pcskeleton/skeleton/skeleton_branches.h"

#include "pcskeleton/core/errors.h"
#include "pcskeleton/internal/disjoint_sets.h"
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

// The length of each bone of a path: bones[i] joins path[i - 1] and path[i] (bones[0] = 0).
std::vector<double> boneLengths(const SkeletonGraph& skeleton, const std::vector<int>& path) {
    std::vector<double> bones(path.size(), 0.0);
    for (std::size_t i = 1; i < path.size(); ++i) bones[i] = (skeleton.nodes[path[i]] - skeleton.nodes[path[i - 1]]).norm();
    return bones;
}

void measureShape(const SkeletonGraph& skeleton, const std::vector<double>& bones, Branch& branch) {
    const std::vector<int>& path = branch.nodes;
    const auto radius = [&](int n) { return skeleton.radii[std::size_t(n)]; };
    double radiusLength = 0.0;
    for (std::size_t i = 1; i < path.size(); ++i) {
        const double h = bones[i];
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

    for (int root : partRoots(skeleton, options.up, options.root)) {
        if (neighbours[root].empty()) continue;  // an isolated node has no branch
        reached[root] = true;
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
                branch.nodes = walkChain(neighbours, base, next);
                for (std::size_t i = 2; i < branch.nodes.size(); ++i) walk(branch.nodes[i - 1], branch.nodes[i]);
                branch.closesLoop = reached[branch.nodes.back()];
                const std::vector<double> bones = boneLengths(skeleton, branch.nodes);
                measureShape(skeleton, bones, branch);
                const int index = int(branches.size());
                double along = 0.0;
                for (std::size_t i = 1; i < branch.nodes.size(); ++i) {
                    const int n = branch.nodes[i];
                    along += bones[i];
                    reached[n] = true;
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
