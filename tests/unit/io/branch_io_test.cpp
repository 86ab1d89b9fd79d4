// The branch table and the points' branches as files: what is written reads back as the
// branches measured, in CSV and JSON; other names are refused and leave nothing behind.
#include <pcskeleton/io/branch_io.h>
#include <pcskeleton/core/errors.h>
#include "support/temp_dir.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

using namespace pcskeleton;
using pcskeleton::testing::TempDir;

namespace {

std::string contents(const std::string& path) {
    std::ifstream in(path);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// A stem of length 1 along z going on for 0.6, and an arm of length 0.5 along x from its
// top; one point per node and one without a node. At the junction (node 2) each branch has
// the radius of its nearest node outside it (skeleton_branches.h): the stem's tip 0.15.
SkeletonBranches stemAndArm() {
    SkeletonGraph g;
    g.nodes = {Point(0, 0, 0), Point(0, 0, 0.5), Point(0, 0, 1), Point(0.5, 0, 1), Point(0, 0, 1.6)};
    g.radii = {0.2, 0.15, 0.1, 0.05, 0.1};
    g.edges = {{0, 1}, {1, 2}, {2, 3}, {2, 4}};
    g.pointNode = {0, 1, 2, 3, 4, -1};
    return measureBranches(g);
}

}  // namespace

TEST(BranchIo, TheCsvTableHasAHeaderAndOneRowPerBranch) {
    const TempDir dir;
    const std::string path = dir.file("branches.csv");
    writeBranchTable(stemAndArm(), path);
    const std::string text = contents(path);
    EXPECT_EQ(text.substr(0, text.find('\n')),
              "branch,parent,order,base_node,tip_node,nodes,length,chord,base_radius,tip_radius,mean_radius,volume,"
              "angle_to_parent,points,closes_loop,part,profile_along,profile_radius");
    EXPECT_NE(text.find("\n0,-1,1,0,2,3,1,1,0.20000000000000001,0.14999999999999999,"), std::string::npos) << text;
    // The stem's profile: its three nodes 0.5 apart, the junction's radius its neighbour's.
    EXPECT_NE(text.find(",,3,false,0,0 0.5 1,0.20000000000000001 0.14999999999999999 0.14999999999999999\n"),
              std::string::npos) << "no angle for the root branch, then the profile: " << text;
    EXPECT_NE(text.find("\n1,0,2,2,3,2,0.5,0.5,"), std::string::npos) << "the arm, order 2: " << text;
    EXPECT_NE(text.find(",90,1,false,0,"), std::string::npos) << "at right angles to the stem: " << text;
}

TEST(BranchIo, TheJsonTableIsAnArrayOfObjects) {
    const TempDir dir;
    const std::string path = dir.file("branches.json");
    writeBranchTable(stemAndArm(), path);
    const std::string text = contents(path);
    EXPECT_EQ(text.front(), '[');
    EXPECT_NE(text.find("{\"branch\": 0, \"parent\": -1, \"order\": 1,"), std::string::npos) << text;
    EXPECT_NE(text.find("\"angle_to_parent\": null"), std::string::npos) << text;
    EXPECT_NE(text.find("\"closes_loop\": false, \"part\": 0, \"profile_along\": [0, 0.60000000000000009], "
                        "\"profile_radius\": [0.10000000000000001, 0.10000000000000001]}\n]"),
              std::string::npos)
        << text;
}

TEST(BranchIo, EachPointsBranchAndPlace) {
    const TempDir dir;
    const std::string path = dir.file("points.csv");
    writePointBranches(stemAndArm(), path);
    EXPECT_EQ(contents(path), "branch,position\n0,0\n0,0.5\n0,1\n1,1\n2,1\n-1,\n");
}

TEST(BranchIo, OtherNamesAreRefusedAndNothingIsWritten) {
    const TempDir dir;
    for (const char* name : {"branches.txt", "branches"}) {
        EXPECT_THROW(writeBranchTable(stemAndArm(), dir.file(name)), InvalidInput) << name;
        EXPECT_FALSE(std::filesystem::exists(dir.file(name))) << name;
    }
    EXPECT_THROW(writePointBranches(stemAndArm(), dir.file("points.json")), InvalidInput);
    // Volume: the stem's cones 0.2 -> 0.15 -> 0.15 (0.0837758), the arm at 0.05 (0.00392699)
    // and the stem's continuation at 0.1 (0.0188496).
    EXPECT_EQ(describe(stemAndArm()), "3 branches (order 1: 2, order 2: 1), 2.1 long in all, volume 0.106552");
}

TEST(BranchIo, TheReportLineGivesEachPartsTotals) {
    SkeletonGraph g;
    g.nodes = {Point(0, 0, 0), Point(0, 0, 1), Point(5, 0, 0), Point(5, 0, 2)};
    g.radii = {0.1, 0.1, 0.2, 0.2};
    g.edges = {{0, 1}, {2, 3}};
    const SkeletonBranches b = measureBranches(g);
    ASSERT_EQ(b.branches.size(), 2u);
    EXPECT_EQ(b.branches[0].part, 0);
    EXPECT_EQ(b.branches[1].part, 1);
    EXPECT_EQ(describe(b), "2 branches (order 1: 2), 3 long in all, volume 0.282743; in 2 parts: part 0 1 branch, 1 long, "
                           "volume 0.0314159, part 1 1 branch, 2 long, volume 0.251327");
    const TempDir dir;
    writeBranchTable(b, dir.file("parts.csv"));
    const std::string text = contents(dir.file("parts.csv"));
    EXPECT_NE(text.find(",closes_loop,part,"), std::string::npos) << text;
    EXPECT_NE(text.find(",false,1,"), std::string::npos) << text;
}

TEST(BranchIo, ASelectionIsDescribedByTheBranchesItLiesOn) {
    const SkeletonBranches b = stemAndArm();
    EXPECT_EQ(describeBranchesOf(b, {1}), "branch 0: order 1, 1 long, radius 0.2 at the base and 0.15 at the tip");
    EXPECT_EQ(describeBranchesOf(b, {3, 4}), "2 branches, 1.1 long in all");
    EXPECT_EQ(describeBranchesOf(b, {}), "");
    EXPECT_EQ(describeBranchesOf(b, {-1, 99}), "") << "nodes that are none are ignored";
}
