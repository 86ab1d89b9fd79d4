// The editing operations on small graphs whose result is known node by node.
#include <pcskeleton/editing/skeleton_editing.h>

#include <gtest/gtest.h>

#include <cmath>

namespace pcskeleton {
namespace {

// A path 0-1-2-3 along x (node i at x = i, radius i + 1) and a tip 4 off node 1 at y = 1;
// ten points, two per node.
SkeletonGraph tShape() {
    SkeletonGraph g;
    for (int i = 0; i < 4; ++i) g.nodes.emplace_back(i, 0, 0);
    g.nodes.emplace_back(1, 1, 0);
    g.radii = {1, 2, 3, 4, 5};
    g.edges = {{0, 1}, {1, 2}, {2, 3}, {1, 4}};
    normalizeEdges(g.edges);
    g.pointNode = {0, 0, 1, 1, 2, 2, 3, 3, 4, 4};
    return g;
}

// Asserts the invariants and that the correspondence matches the graph's size.
void expectValid(const SkeletonEditor& editor) {
    const SkeletonGraph g = editor.skeleton();
    EXPECT_EQ(invariantViolation(g), "");
    EXPECT_EQ(g.pointNode.size(), 10u);
}

bool connected(const SkeletonGraph& g, int a, int b) {
    return std::find(g.edges.begin(), g.edges.end(), Edge{std::min(a, b), std::max(a, b)}) != g.edges.end();
}

TEST(SkeletonEditing, MoveShiftsOnlyTheGivenNodes) {
    SkeletonEditor editor(tShape());
    editor.moveNodes({1, 3}, Point(0, 0, 2));
    EXPECT_EQ(editor.graph().nodes[1], Point(1, 0, 2));
    EXPECT_EQ(editor.graph().nodes[3], Point(3, 0, 2));
    EXPECT_EQ(editor.graph().nodes[2], Point(2, 0, 0));
    EXPECT_EQ(editor.undoText(), "move 2 nodes");
    expectValid(editor);
}

TEST(SkeletonEditing, DeleteRemovesEdgesRenumbersAndOrphansPoints) {
    SkeletonEditor editor(tShape());
    editor.deleteNodes({1});
    const SkeletonGraph g = editor.skeleton();
    ASSERT_EQ(g.nodeCount(), 4u);
    // Old 2, 3, 4 are now 1, 2, 3; only the bone 2-3 survives.
    EXPECT_EQ(g.nodes[1], Point(2, 0, 0));
    EXPECT_EQ(g.radii[3], 5);
    EXPECT_EQ(g.edges, (std::vector<Edge>{{1, 2}}));
    EXPECT_EQ(g.pointNode, (std::vector<int>{0, 0, -1, -1, 1, 1, 2, 2, 3, 3}));
    expectValid(editor);
}

TEST(SkeletonEditing, DeleteEdgeAndConnect) {
    SkeletonEditor editor(tShape());
    editor.deleteEdge(2, 1);
    EXPECT_FALSE(connected(editor.graph(), 1, 2));
    EXPECT_EQ(analyseTopology(editor.graph()).components, 2);
    editor.connect(3, 4);
    EXPECT_TRUE(connected(editor.graph(), 3, 4));
    EXPECT_EQ(analyseTopology(editor.graph()).components, 1);
    expectValid(editor);
}

TEST(SkeletonEditing, ConnectingCloseALoop) {
    SkeletonEditor editor(tShape());
    editor.connect(4, 3);
    EXPECT_EQ(analyseTopology(editor.graph()).cycles, 1);
}

TEST(SkeletonEditing, MergeMovesToCentroidKeepsOutsideEdgesAndMergesPoints) {
    SkeletonEditor editor(tShape());
    const int merged = editor.mergeNodes({2, 1});
    EXPECT_EQ(merged, 1);
    const SkeletonGraph g = editor.skeleton();
    ASSERT_EQ(g.nodeCount(), 4u);
    EXPECT_TRUE(g.nodes[1].isApprox(Point(1.5, 0, 0)));
    EXPECT_DOUBLE_EQ(g.radii[1], 2.5);
    // Old 0, 3, 4 are now 0, 2, 3, all attached to the merged node; the bone 1-2 is gone.
    EXPECT_EQ(g.edges, (std::vector<Edge>{{0, 1}, {1, 2}, {1, 3}}));
    EXPECT_EQ(g.pointNode, (std::vector<int>{0, 0, 1, 1, 1, 1, 2, 2, 3, 3}));
    expectValid(editor);
}

TEST(SkeletonEditing, MergingALoopsNodesRemovesTheLoop) {
    SkeletonGraph g = tShape();
    g.edges.push_back({3, 4});
    normalizeEdges(g.edges);
    SkeletonEditor editor(g);
    ASSERT_EQ(analyseTopology(editor.graph()).cycles, 1);
    editor.mergeNodes({1, 2, 3, 4});
    EXPECT_EQ(analyseTopology(editor.graph()).cycles, 0);
    EXPECT_EQ(editor.graph().nodeCount(), 2u);
    expectValid(editor);
}

TEST(SkeletonEditing, SplitInsertsANodeOnTheBone) {
    SkeletonEditor editor(tShape());
    const int inserted = editor.splitEdge(2, 3, 0.25);
    EXPECT_EQ(inserted, 5);
    const SkeletonGraph g = editor.skeleton();
    EXPECT_TRUE(g.nodes[5].isApprox(Point(2.25, 0, 0)));
    EXPECT_DOUBLE_EQ(g.radii[5], 3.25);
    EXPECT_FALSE(connected(g, 2, 3));
    EXPECT_TRUE(connected(g, 2, 5));
    EXPECT_TRUE(connected(g, 5, 3));
    EXPECT_EQ(std::count(g.pointNode.begin(), g.pointNode.end(), 5), 0);
    expectValid(editor);
}

// Inferred bones (a bridged gap) stay marked through edits, follow renumbering, become two
// when split, and are gone with their bone.
TEST(SkeletonEditing, InferredBonesFollowTheEdits) {
    SkeletonGraph g = tShape();
    g.inferred = {{2, 3}, {1, 4}};
    SkeletonEditor editor(g);
    editor.moveNodes({3}, Point(0, 0, 1));
    EXPECT_EQ(editor.skeleton().inferred, (std::vector<Edge>{{1, 4}, {2, 3}}));
    editor.deleteNodes({0});  // renumbers: 1->0, 2->1, 3->2, 4->3
    EXPECT_EQ(editor.skeleton().inferred, (std::vector<Edge>{{0, 3}, {1, 2}}));
    const int middle = editor.splitEdge(1, 2, 0.5);
    EXPECT_EQ(editor.skeleton().inferred, (std::vector<Edge>{{0, 3}, {1, middle}, {2, middle}}));
    editor.deleteEdge(0, 3);
    EXPECT_EQ(editor.skeleton().inferred, (std::vector<Edge>{{1, middle}, {2, middle}}));
    editor.connect(0, 3);  // a bone the user draws is not a guess
    EXPECT_EQ(editor.skeleton().inferred, (std::vector<Edge>{{1, middle}, {2, middle}}));
    editor.mergeNodes({1, middle});  // the bone between them collapses
    EXPECT_EQ(editor.skeleton().inferred, (std::vector<Edge>{{1, 2}}));
    expectValid(editor);
    editor.undo();
    editor.undo();
    EXPECT_EQ(editor.skeleton().inferred, (std::vector<Edge>{{1, middle}, {2, middle}}));
}

TEST(SkeletonEditing, AnInferredBoneThatIsNoBoneIsRefused) {
    SkeletonGraph g = tShape();
    g.inferred = {{0, 4}};
    EXPECT_NE(invariantViolation(g).find("inferred bone 0-4 is not a bone"), std::string::npos) << invariantViolation(g);
    EXPECT_THROW(SkeletonEditor{g}, InvalidInput);
}

TEST(SkeletonEditing, RadiusSetAndScaled) {
    SkeletonEditor editor(tShape());
    editor.setRadius({0, 4}, 0.5);
    EXPECT_EQ(editor.graph().radii, (std::vector<double>{0.5, 2, 3, 4, 0.5}));
    editor.scaleRadius({1, 4}, 2.0);
    EXPECT_EQ(editor.graph().radii, (std::vector<double>{0.5, 4, 3, 4, 1}));
}

TEST(SkeletonEditing, UndoAndRedoWalkTheHistory) {
    const SkeletonGraph original = tShape();
    SkeletonEditor editor(original);
    EXPECT_FALSE(editor.canUndo());
    editor.deleteNodes({4});
    editor.mergeNodes({0, 1});
    const SkeletonGraph afterMerge = editor.skeleton();
    EXPECT_EQ(editor.undoText(), "merge 2 nodes");

    editor.undo();
    EXPECT_EQ(editor.graph().nodeCount(), 4u);
    EXPECT_EQ(editor.redoText(), "merge 2 nodes");
    editor.undo();
    EXPECT_FALSE(editor.canUndo());
    EXPECT_EQ(editor.skeleton().nodes, original.nodes);
    EXPECT_EQ(editor.skeleton().edges, original.edges);
    EXPECT_EQ(editor.skeleton().pointNode, original.pointNode);

    editor.redo();
    editor.redo();
    EXPECT_FALSE(editor.canRedo());
    EXPECT_EQ(editor.skeleton().nodes, afterMerge.nodes);
    EXPECT_EQ(editor.skeleton().edges, afterMerge.edges);
    EXPECT_EQ(editor.skeleton().pointNode, afterMerge.pointNode);

    // A new operation after an undo discards what could have been redone.
    editor.undo();
    editor.connect(0, 2);
    EXPECT_FALSE(editor.canRedo());
}

TEST(SkeletonEditing, RevisionCountsChangesUndoAndRedo) {
    SkeletonEditor editor(tShape());
    const std::size_t start = editor.revision();
    editor.scaleRadius({0}, 2.0);
    editor.undo();
    editor.redo();
    EXPECT_EQ(editor.revision(), start + 3);
}

TEST(SkeletonEditing, HistoryIsBounded) {
    SkeletonEditor editor(tShape());
    for (std::size_t i = 0; i < SkeletonEditor::kUndoLimit + 10; ++i) editor.moveNodes({0}, Point(1, 0, 0));
    std::size_t undone = 0;
    while (editor.canUndo()) editor.undo(), ++undone;
    EXPECT_EQ(undone, SkeletonEditor::kUndoLimit);
    EXPECT_EQ(editor.graph().nodes[0], Point(10, 0, 0));
}

// Each refused operation leaves the skeleton and the history as they were.
TEST(SkeletonEditing, RefusedOperationsChangeNothing) {
    SkeletonEditor editor(tShape());
    const auto refused = [&](auto&& operation, const char* reason) {
        const std::size_t revision = editor.revision();
        try {
            operation();
            ADD_FAILURE() << "accepted; expected a refusal mentioning '" << reason << "'";
        } catch (const InvalidInput& e) {
            EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
        }
        EXPECT_EQ(editor.revision(), revision);
        EXPECT_EQ(editor.graph().nodeCount(), 5u);
        EXPECT_EQ(editor.graph().edgeCount(), 4u);
    };
    refused([&] { editor.connect(2, 2); }, "itself");
    refused([&] { editor.connect(1, 2); }, "already connected");
    refused([&] { editor.connect(1, 9); }, "does not exist");
    refused([&] { editor.deleteEdge(0, 3); }, "not connected");
    refused([&] { editor.deleteNodes({}); }, "at least 1 node");
    refused([&] { editor.mergeNodes({3, 3}); }, "at least 2 nodes");
    refused([&] { editor.splitEdge(0, 2); }, "not connected");
    refused([&] { editor.splitEdge(0, 1, 1.0); }, "strictly between");
    refused([&] { editor.setRadius({0}, 0.0); }, "positive");
    refused([&] { editor.setRadius({0}, NAN); }, "positive");
    refused([&] { editor.scaleRadius({0}, -1.0); }, "positive");
    refused([&] { editor.moveNodes({0}, Point(INFINITY, 0, 0)); }, "non-finite");
    refused([&] { editor.moveNodes({-1}, Point(1, 0, 0)); }, "does not exist");
    EXPECT_FALSE(editor.canUndo());
}

TEST(SkeletonEditing, InvalidSkeletonsAreRefusedWithTheReason) {
    const auto reason = [](SkeletonGraph g) {
        try {
            SkeletonEditor editor(std::move(g));
        } catch (const InvalidInput& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    SkeletonGraph zeroRadius = tShape();
    zeroRadius.radii[2] = 0;
    EXPECT_NE(reason(zeroRadius).find("node 2 has radius 0"), std::string::npos);
    SkeletonGraph dangling = tShape();
    dangling.edges.push_back({3, 7});
    EXPECT_NE(reason(dangling).find("does not exist"), std::string::npos);
    SkeletonGraph selfLoop = tShape();
    selfLoop.edges.push_back({2, 2});
    EXPECT_NE(reason(selfLoop).find("connected to itself"), std::string::npos);
    SkeletonGraph twice = tShape();
    twice.edges.push_back({1, 0});
    EXPECT_NE(reason(twice).find("connected twice"), std::string::npos);
    SkeletonGraph badPoint = tShape();
    badPoint.pointNode[0] = 5;
    EXPECT_NE(reason(badPoint).find("a point belongs to node 5"), std::string::npos);
}

TEST(SkeletonEditing, MissingRadiiComeFromTheNearestNodesThatHaveOne) {
    SkeletonGraph g = tShape();
    g.radii = {0, 2, NAN, -1, 6};  // 0 is next to 1; 2 next to 1; 3 only reaches 2
    EXPECT_EQ(fillMissingRadii(g), 3);
    EXPECT_DOUBLE_EQ(g.radii[0], 2);
    EXPECT_DOUBLE_EQ(g.radii[2], 2);
    EXPECT_DOUBLE_EQ(g.radii[3], 2);
    EXPECT_DOUBLE_EQ(g.radii[4], 6);

    SkeletonGraph noRadius = tShape();
    noRadius.radii.assign(5, 0.0);
    EXPECT_EQ(fillMissingRadii(noRadius), 5);
    for (double r : noRadius.radii) EXPECT_DOUBLE_EQ(r, 0.5);  // half the unit bone length
    EXPECT_EQ(invariantViolation(noRadius), "");
}

}  // namespace
}  // namespace pcskeleton
