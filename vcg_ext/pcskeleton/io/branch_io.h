// The branch table (skeleton_branches.h) as a file: CSV for spreadsheets and data frames,
// JSON for programs; and each point's branch and place along it.
#pragma once

#include "pcskeleton/skeleton/skeleton_branches.h"

#include <string>
#include <vector>

namespace pcskeleton {

// True for the names writeBranchTable writes: .csv or .json.
bool isBranchTableFileName(const std::string& path);

// One row (CSV, with a header) or object (JSON, an array) per branch: branch, parent,
// order, base_node, tip_node, nodes, length, chord, base_radius, tip_radius, mean_radius,
// volume, angle_to_parent (degrees; empty in CSV and null in JSON for a root branch),
// points, closes_loop, part, and the radius profile: profile_along and profile_radius,
// one number per node from base to tip (space-separated in CSV, arrays in JSON). Written
// atomically; throws InvalidInput.
void writeBranchTable(const SkeletonBranches& branches, const std::string& path);

// A CSV file, "branch,position" then one line per input point in the input's order: its
// branch (-1 for a point with no node) and its place along it, 0 at the base and 1 at the
// tip (empty for none). Written atomically; throws InvalidInput.
void writePointBranches(const SkeletonBranches& branches, const std::string& path);

// What a selection of nodes lies on (6 significant digits): "branch 3: order 2, 0.42 long,
// radius 0.05 at the base and 0.03 at the tip" for nodes of one branch, "3 branches,
// 1.27 long in all" for nodes of several, "" for none. Nodes without a branch are ignored.
std::string describeBranchesOf(const SkeletonBranches& branches, const std::vector<int>& nodes);

// "7 branches (order 1: 2, order 2: 5), 3.42 long in all, volume 0.12" (6 significant
// digits), then for a skeleton of several parts "; in 2 parts: part 0 5 branches, 2.1 long,
// volume 0.1, part 1 ..." (the first ten): the report's line.
std::string describe(const SkeletonBranches& branches);

}  // namespace pcskeleton
