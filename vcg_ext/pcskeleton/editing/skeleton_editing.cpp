#include "pcskeleton/editing/skeleton_editing.h"

#include "pcskeleton/internal/counted.h"

#include <algorithm>
#include <functional>
#include <numeric>

namespace pcskeleton {

std::array<int, 2> exactlyTwoNodes(const std::vector<int>& nodes, const std::string& purpose) {
    if (nodes.size() != 2) {
        throw InvalidInput("To " + purpose + ", select exactly two nodes (" + std::to_string(nodes.size()) +
                           " selected).");
    }
    return {nodes[0], nodes[1]};
}

SkeletonEditor::SkeletonEditor(SkeletonGraph skeleton) {
    const std::string violation = invariantViolation(skeleton);
    if (!violation.empty()) throw InvalidInput("This skeleton cannot be edited: " + violation + ".");
    initialPointNode_ = std::move(skeleton.pointNode);
    skeleton.pointNode.clear();
    normalizeEdges(skeleton.edges);
    keepInferredWithinEdges(skeleton);
    current_.originNode.resize(skeleton.nodeCount());
    std::iota(current_.originNode.begin(), current_.originNode.end(), 0);
    current_.graph = std::move(skeleton);
}

std::vector<int> SkeletonEditor::correspondence() const {
    std::vector<int> node(initialPointNode_.size(), -1);
    for (std::size_t i = 0; i < node.size(); ++i) {
        if (initialPointNode_[i] >= 0) node[i] = current_.originNode[initialPointNode_[i]];
    }
    return node;
}

SkeletonGraph SkeletonEditor::skeleton() const {
    SkeletonGraph result = current_.graph;
    result.pointNode = correspondence();
    return result;
}

void SkeletonEditor::checkNode(int node) const {
    if (node < 0 || node >= static_cast<int>(current_.graph.nodeCount())) {
        throw InvalidInput("Node " + std::to_string(node) + " does not exist (the skeleton has " +
                           counted(current_.graph.nodeCount(), "node") + ").");
    }
}

std::vector<int> SkeletonEditor::checkedNodes(std::vector<int> nodes, std::size_t atLeast,
                                              const char* operation) const {
    for (int n : nodes) checkNode(n);
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    if (nodes.size() < atLeast) {
        throw InvalidInput(std::string("To ") + operation + ", select at least " + counted(atLeast, "node") +
                           " (" + std::to_string(nodes.size()) + " selected).");
    }
    return nodes;
}

void SkeletonEditor::commit(State next) {
    keepInferredWithinEdges(next.graph);  // a deleted or merged bone is no longer inferred
    const std::string violation = invariantViolation(next.graph);
    if (!violation.empty()) throw InvalidInput("Cannot " + next.what + ": " + violation + ".");
    undo_.push_back(std::move(current_));
    if (undo_.size() > kUndoLimit) undo_.erase(undo_.begin());
    current_ = std::move(next);
    redo_.clear();
    ++revision_;
}

void SkeletonEditor::removeNodes(State& state, const std::vector<bool>& doomed) {
    SkeletonGraph& g = state.graph;
    std::vector<int> newIndex(g.nodeCount(), -1);
    int kept = 0;
    for (std::size_t n = 0; n < g.nodeCount(); ++n) {
        if (!doomed[n]) {
            newIndex[n] = kept;
            g.nodes[kept] = g.nodes[n];
            g.radii[kept] = g.radii[n];
            ++kept;
        }
    }
    g.nodes.resize(kept);
    g.radii.resize(kept);
    const auto renumbered = [&newIndex](const std::vector<Edge>& old) {
        std::vector<Edge> edges;
        for (const Edge& e : old) {
            if (newIndex[e[0]] >= 0 && newIndex[e[1]] >= 0) edges.push_back({newIndex[e[0]], newIndex[e[1]]});
        }
        normalizeEdges(edges);
        return edges;
    };
    g.edges = renumbered(g.edges);
    g.inferred = renumbered(g.inferred);
    for (int& node : state.originNode) {
        if (node >= 0) node = newIndex[node];
    }
}

void SkeletonEditor::moveNodes(const std::vector<int>& nodes, const Point& offset) {
    const std::vector<int> moved = checkedNodes(nodes, 1, "move nodes");
    if (!offset.allFinite()) throw InvalidInput("Cannot move nodes by a non-finite offset.");
    State next = current_;
    next.what = "move " + counted(moved.size(), "node");
    for (int n : moved) next.graph.nodes[n] += offset;
    commit(std::move(next));
}

void SkeletonEditor::deleteNodes(const std::vector<int>& nodes) {
    const std::vector<int> deleted = checkedNodes(nodes, 1, "delete nodes");
    State next = current_;
    next.what = "delete " + counted(deleted.size(), "node");
    std::vector<bool> doomed(current_.graph.nodeCount(), false);
    for (int n : deleted) doomed[n] = true;
    removeNodes(next, doomed);
    commit(std::move(next));
}

void SkeletonEditor::deleteEdge(int a, int b) {
    checkNode(a);
    checkNode(b);
    if (!hasEdge(current_.graph.edges, a, b)) {
        throw InvalidInput("Nodes " + std::to_string(a) + " and " + std::to_string(b) + " are not connected.");
    }
    State next = current_;
    next.what = "delete an edge";
    auto& edges = next.graph.edges;
    edges.erase(std::find(edges.begin(), edges.end(), edgeBetween(a, b)));
    commit(std::move(next));
}

void SkeletonEditor::connect(int a, int b) {
    checkNode(a);
    checkNode(b);
    if (a == b) throw InvalidInput("A node cannot be connected to itself: select two different nodes.");
    if (hasEdge(current_.graph.edges, a, b)) {
        throw InvalidInput("Nodes " + std::to_string(a) + " and " + std::to_string(b) + " are already connected.");
    }
    State next = current_;
    next.what = "connect two nodes";
    next.graph.edges.push_back({a, b});
    normalizeEdges(next.graph.edges);
    commit(std::move(next));
}

int SkeletonEditor::mergeNodes(const std::vector<int>& nodes) {
    const std::vector<int> merged = checkedNodes(nodes, 2, "merge nodes");
    State next = current_;
    next.what = "merge " + counted(merged.size(), "node");
    SkeletonGraph& g = next.graph;

    // The lowest of the merged indices survives and becomes the merged node, so removing the
    // others leaves it at the same index.
    const int kept = merged.front();
    Point centroid = Point::Zero();
    double radius = 0.0;
    for (int n : merged) centroid += g.nodes[n], radius += g.radii[n];
    g.nodes[kept] = centroid / double(merged.size());
    g.radii[kept] = radius / double(merged.size());

    std::vector<bool> doomed(g.nodeCount(), false);
    for (int n : merged) doomed[n] = n != kept;
    for (std::vector<Edge>* edges : {&g.edges, &g.inferred}) {
        for (Edge& e : *edges) {
            for (int& end : e) {
                if (doomed[end]) end = kept;
            }
        }
        normalizeEdges(*edges);  // drops the edges that were inside the merged set
    }
    for (int& node : next.originNode) {
        if (node >= 0 && doomed[node]) node = kept;
    }
    removeNodes(next, doomed);
    commit(std::move(next));
    return kept;
}

int SkeletonEditor::splitEdge(int a, int b, double at) {
    checkNode(a);
    checkNode(b);
    if (!hasEdge(current_.graph.edges, a, b)) {
        throw InvalidInput("To split a bone, select the two nodes at its ends (nodes " + std::to_string(a) +
                           " and " + std::to_string(b) + " are not connected).");
    }
    if (!(at > 0.0 && at < 1.0)) throw InvalidInput("A bone is split strictly between its ends (0 < at < 1).");
    State next = current_;
    next.what = "split a bone";
    SkeletonGraph& g = next.graph;
    const int inserted = static_cast<int>(g.nodeCount());
    g.nodes.push_back((1.0 - at) * g.nodes[a] + at * g.nodes[b]);
    g.radii.push_back((1.0 - at) * g.radii[a] + at * g.radii[b]);
    const Edge split = edgeBetween(a, b);
    g.edges.erase(std::find(g.edges.begin(), g.edges.end(), split));
    g.edges.push_back({a, inserted});
    g.edges.push_back({b, inserted});
    normalizeEdges(g.edges);
    if (std::binary_search(g.inferred.begin(), g.inferred.end(), split)) {  // both halves stay guessed
        g.inferred.push_back({a, inserted});
        g.inferred.push_back({b, inserted});
    }
    commit(std::move(next));
    return inserted;
}

void SkeletonEditor::setRadius(const std::vector<int>& nodes, double radius) {
    if (!isPositiveFinite(radius)) {
        throw InvalidInput("A radius must be positive and finite (got " + std::to_string(radius) + ").");
    }
    changeRadii(nodes, "set", [radius](double) { return radius; });
}

void SkeletonEditor::scaleRadius(const std::vector<int>& nodes, double factor) {
    if (!isPositiveFinite(factor)) {
        throw InvalidInput("A radius scale factor must be positive and finite (got " + std::to_string(factor) + ").");
    }
    changeRadii(nodes, "scale", [factor](double radius) { return radius * factor; });
}

void SkeletonEditor::changeRadii(const std::vector<int>& nodes, const std::string& verb,
                                 const std::function<double(double)>& newRadius) {
    const std::vector<int> changed = checkedNodes(nodes, 1, (verb + " a radius").c_str());
    State next = current_;
    next.what = verb + " the radius of " + counted(changed.size(), "node");
    for (int n : changed) next.graph.radii[n] = newRadius(next.graph.radii[n]);
    commit(std::move(next));
}

void SkeletonEditor::undo() {
    if (undo_.empty()) return;
    redo_.push_back(std::move(current_));
    current_ = std::move(undo_.back());
    undo_.pop_back();
    ++revision_;
}

void SkeletonEditor::redo() {
    if (redo_.empty()) return;
    undo_.push_back(std::move(current_));
    current_ = std::move(redo_.back());
    redo_.pop_back();
    ++revision_;
}

}  // namespace pcskeleton
