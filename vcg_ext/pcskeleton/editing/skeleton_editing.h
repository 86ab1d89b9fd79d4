// Hand repairs of a skeleton (paper Fig. 1 and 14: a wrong loop removed, a missing bone
// added, a radius changed) as operations that keep the graph valid and can be undone.
//
// Every operation either applies completely or throws InvalidInput and leaves the
// skeleton as it was. The invariants of invariantViolation() are checked after each one.
// Node indices are dense: deleting or merging renumbers the nodes after the removed ones,
// in order, so index i stays the i-th surviving node.
//
// The correspondence follows the edits: a deleted node's points belong to no node (-1), a
// merged node's points to the merged node, a node made by splitting owns no points.
// Undo history keeps node-sized states only (not one entry per input point), so it stays
// small on million-point clouds.
#pragma once

#include "pcskeleton/skeleton/skeleton_graph.h"

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace pcskeleton {

// The two nodes of a selection meant for a two-node operation (connect, disconnect, split);
// throws InvalidInput naming `purpose` ("connect nodes") when there are not exactly two.
std::array<int, 2> exactlyTwoNodes(const std::vector<int>& nodes, const std::string& purpose);

class SkeletonEditor {
public:
    static constexpr std::size_t kUndoLimit = 500;  // oldest steps are forgotten beyond this

    // Throws InvalidInput when the skeleton breaks an invariant (fill missing radii first:
    // fillMissingRadii).
    explicit SkeletonEditor(SkeletonGraph skeleton);

    // Nodes, edges and radii; pointNode is left empty here: see correspondence().
    const SkeletonGraph& graph() const { return current_.graph; }
    // The node of each input point (-1: none).
    std::vector<int> correspondence() const;
    // graph() with the correspondence filled in.
    SkeletonGraph skeleton() const;

    void moveNodes(const std::vector<int>& nodes, const Point& offset);
    void deleteNodes(const std::vector<int>& nodes);
    void deleteEdge(int a, int b);
    void connect(int a, int b);
    // Replaces the nodes by one at their centroid, with their mean radius, their edges to
    // other nodes and all their points. Returns its index.
    int mergeNodes(const std::vector<int>& nodes);
    // Inserts a node on the bone a-b at fraction `at` from a (radius interpolated too).
    // Returns its index (the last one).
    int splitEdge(int a, int b, double at = 0.5);
    void setRadius(const std::vector<int>& nodes, double radius);
    void scaleRadius(const std::vector<int>& nodes, double factor);

    bool canUndo() const { return !undo_.empty(); }
    bool canRedo() const { return !redo_.empty(); }
    // What undo() / redo() would revert or repeat, e.g. "merge 3 nodes"; empty if nothing.
    std::string undoText() const { return undo_.empty() ? std::string() : current_.what; }
    std::string redoText() const { return redo_.empty() ? std::string() : redo_.back().what; }
    void undo();
    void redo();
    // Increases with every change, undo and redo included: views compare it to redraw.
    std::size_t revision() const { return revision_; }

private:
    struct State {
        SkeletonGraph graph;          // pointNode empty
        std::vector<int> originNode;  // node now standing for each node of the initial skeleton
        std::string what;             // the operation that led to this state
    };

    // Validates `next` and makes it current, remembering the present state for undo.
    void commit(State next);
    // Drops `doomed` nodes (and their edges); the others are renumbered densely.
    static void removeNodes(State& state, const std::vector<bool>& doomed);
    void changeRadii(const std::vector<int>& nodes, const std::string& verb,
                     const std::function<double(double)>& newRadius);
    std::vector<int> checkedNodes(std::vector<int> nodes, std::size_t atLeast, const char* operation) const;
    void checkNode(int node) const;

    std::vector<int> initialPointNode_;  // the correspondence given to the constructor
    State current_;
    std::vector<State> undo_, redo_;
    std::size_t revision_ = 0;
};

}  // namespace pcskeleton
