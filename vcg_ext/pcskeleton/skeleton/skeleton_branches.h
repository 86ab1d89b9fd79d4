// The skeleton as branches, and what people measure with them: a plant's stem and leaf
// lengths, a tree's branch lengths, radii and volume, a limb's angle, which points belong
// to which part.
//
// A branch is a maximal chain of bones between tips and junctions (a whole loop, when a
// part is one). Each part of the skeleton grows from a root node, by default its lowest
// node along an "up" axis (the base of a plant or a tree). Branches run from their base (at
// the root, or at the junction where they leave their parent) to their tip. Orders follow
// the botanists' and foresters' convention: 1 for the main axis from the root, 2 for what
// grows from it, and so on; at each junction the main axis goes on into the child with the
// longest continuation (the longest path of branches from there to a tip), the others
// start a new order.
//
// Measured as the object lies, not as the nodes do: a branch runs from the fork point of
// its base junction (where the lines along the junction's arms meet) to that of its tip's
// or to its tip, along its nodes smoothed across (the zigzag of scattered nodes taken out,
// bends kept). Junctions whose spheres overlap (fork points closer than their two radii)
// are one knot, their arms leaving it together: contraction splits a junction of four or
// more arms in two. At a junction a branch has the radius of its nearest node outside it.
#pragma once

#include "pcskeleton/skeleton/skeleton_graph.h"

#include <vector>

namespace pcskeleton {

struct Branch {
    std::vector<int> nodes;  // from the base to the tip (the base is on the parent, or the root)
    int parent = -1;         // the branch it grows from; -1 for a branch from its part's root
    int part = 0;            // the connected part of the skeleton it is in, numbered from 0
    int order = 1;
    bool closesLoop = false;  // it ends where the skeleton was reached already: it closes a loop
    double length = 0.0;      // along the bones (see above), input units
    double chord = 0.0;       // from base to tip in a straight line
    double baseRadius = 0.0, tipRadius = 0.0;
    double meanRadius = 0.0;  // along its length
    // The radius profile: per node of `nodes`, its distance from the base along the branch
    // and the branch's radius there.
    std::vector<double> along, radii;
    double volume = 0.0;      // the bones as truncated cones of the nodes' radii
    // Degrees between the parent's direction where it ends and this branch's where it starts
    // (0: straight on); NaN for a branch from the root.
    double angleToParent = 0.0;
    int points = 0;  // input points of the branch (pointBranch)
};

struct BranchOptions {
    Point up = Point::UnitZ();  // the root of each part is its lowest node along `up`...
    int root = -1;              // ...except the part of this node, which grows from it (-1: none)
};

struct SkeletonBranches {
    std::vector<Branch> branches;  // each part's branches from its root outwards
    // Per node: its branch (a junction belongs to the branch that reaches it, the root to its
    // first branch); -1 for an isolated node.
    std::vector<int> nodeBranch;
    std::vector<int> pointBranch;       // per input point (skeleton.pointNode's), -1 for none
    std::vector<double> pointPosition;  // per input point: 0 at its branch's base, 1 at its tip
};

// Throws InvalidInput for an `up` axis of zero length or a root that is not a node.
// Each input point goes to its node's branch; a junction's node holds points of all its
// arms, and they all go to the branch that reaches it.
SkeletonBranches measureBranches(const SkeletonGraph& skeleton, const BranchOptions& options = {});

// The same, with the skeleton's input points (`points[i]` is the point of
// skeleton.pointNode[i]): the points of a junction, or of a knot of junctions, go each to
// the branch it lies along (the one whose course near the knot passes nearest it), at its
// place along that branch.
SkeletonBranches measureBranches(const SkeletonGraph& skeleton, const PointList& points,
                                 const BranchOptions& options = {});

}  // namespace pcskeleton
