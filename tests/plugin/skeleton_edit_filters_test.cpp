// The scriptable skeleton repairs (delete, connect, merge, set radius of the selected
// nodes) through the real plugin .so, on layers whose answer is known.
#include "plugin_fixture.h"

#include "support/sampled_shapes.h"
#include <pcskeleton/skeleton/skeleton_graph.h>

namespace {

using Allocator = vcg::tri::Allocator<CMeshO>;

class SkeletonEditFilterTest : public FilterPluginTest {
protected:
    // Nodes 0..4 at x = 0..4 with radius (quality) 0.1 * (i + 1), bones i-(i+1): what
    // MeshLab makes of a skeleton PLY opened from a file.
    MeshModel* addPathSkeleton() {
        MeshModel* m = document.addNewMesh("", "path skeleton", true);
        m->updateDataMask(MeshModel::MM_VERTQUALITY);
        auto v = Allocator::AddVertices(m->cm, 5);
        for (int i = 0; i < 5; ++i, ++v) v->P() = vcg::Point3f(i, 0, 0), v->Q() = 0.1f * (i + 1);
        for (int i = 0; i < 4; ++i) Allocator::AddEdge(m->cm, i, i + 1);
        return m;
    }

    bool applyDefaults(const char* filter) { return apply(action(filter), defaults(action(filter))); }
};

void select(MeshModel& m, std::initializer_list<int> vertices) {
    for (auto& v : m.cm.vert) v.ClearS();
    for (int i : vertices) m.cm.vert[i].SetS();
}

std::vector<int> selectedVertices(const MeshModel& m) {
    std::vector<int> selected;
    for (std::size_t i = 0; i < m.cm.vert.size(); ++i)
        if (!m.cm.vert[i].IsD() && m.cm.vert[i].IsS()) selected.push_back(int(i));
    return selected;
}

}  // namespace

TEST_F(SkeletonEditFilterTest, DeclaredAsInPlaceEditsWithHelpText) {
    addPathSkeleton();
    for (const char* name : {kDeleteFilter, kConnectFilter, kMergeFilter, kRadiusFilter}) {
        QAction* a = action(name);
        ASSERT_NE(a, nullptr) << name;
        EXPECT_NE(plugin->filterInfo(a).indexOf("selected"), -1) << name;
        EXPECT_TRUE(plugin->postCondition(a) & MeshModel::MM_VERTNUMBER) << name << ": MeshLab must redraw the layer";
        for (const RichParameter& p : defaults(a)) EXPECT_FALSE(p.toolTip().isEmpty()) << name;
    }
}

// The paper's Fig. 1 repair in reverse: removing nodes cuts the torus's loop, and their
// points lose their node while every other point keeps a valid one.
TEST_F(SkeletonEditFilterTest, DeletingSelectedNodesCutsTheTorusLoop) {
    MeshModel* input = addPointLayer(pcskeleton::shapes::torus(3000, 1.0, 0.25), "torus");
    const auto before = positionsOf(*input);
    QAction* compute = action(kSkeletonFilter);
    RichParameterList parameters = defaults(compute);
    parameters.setValue("addSegmentsLayer", BoolValue(false));
    ASSERT_TRUE(apply(compute, parameters)) << plugin->errorMsg().toStdString();
    MeshModel* skeleton = document.mm();
    ASSERT_EQ(topologyOfLayer(*skeleton).cycles, 1);
    const int nodesBefore = skeleton->cm.vn;

    int doomed = 0;
    for (auto& v : skeleton->cm.vert) {
        if (v.cP()[0] > 0.8f) v.SetS(), ++doomed;
    }
    ASSERT_GT(doomed, 0);
    ASSERT_TRUE(applyDefaults(kDeleteFilter)) << plugin->errorMsg().toStdString();

    const pcskeleton::SkeletonTopology t = topologyOfLayer(*skeleton);
    EXPECT_EQ(t.nodes, nodesBefore - doomed);
    EXPECT_EQ(t.cycles, 0) << pcskeleton::describe(t);
    EXPECT_EQ(t.tips, 2) << pcskeleton::describe(t);
    EXPECT_TRUE(selectedVertices(*skeleton).empty());
    EXPECT_EQ(positionsOf(*input), before);

    auto correspondence = Allocator::FindPerMeshAttribute<std::vector<int>>(skeleton->cm, "pcs_correspondence");
    ASSERT_TRUE(Allocator::IsValidHandle(skeleton->cm, correspondence));
    ASSERT_EQ(correspondence().size(), input->cm.vert.size());
    int orphans = 0;
    for (std::size_t i = 0; i < correspondence().size(); ++i) {
        const int node = correspondence()[i];
        ASSERT_LT(node, skeleton->cm.vn);
        if (node < 0) {
            ++orphans;
            EXPECT_GT(input->cm.vert[i].cP()[0], 0.4f) << "point " << i << " lost its node far from the cut";
        } else {
            EXPECT_LT(vcg::Distance(input->cm.vert[i].cP(), skeleton->cm.vert[node].cP()), 0.5f) << "point " << i;
        }
    }
    EXPECT_GT(orphans, 0);
}

TEST_F(SkeletonEditFilterTest, ConnectingTheTwoEndsOfAPathMakesALoop) {
    MeshModel* path = addPathSkeleton();
    select(*path, {0, 4});
    ASSERT_TRUE(applyDefaults(kConnectFilter)) << plugin->errorMsg().toStdString();
    const pcskeleton::SkeletonTopology t = topologyOfLayer(*path);
    EXPECT_EQ(t.edges, 5);
    EXPECT_EQ(t.cycles, 1);
    EXPECT_EQ(t.tips, 0);
    EXPECT_EQ(selectedVertices(*path), (std::vector<int>{0, 4}));
}

TEST_F(SkeletonEditFilterTest, MergingTwoNodesPlacesOneAtTheirCentroid) {
    MeshModel* path = addPathSkeleton();
    select(*path, {1, 2});
    ASSERT_TRUE(applyDefaults(kMergeFilter)) << plugin->errorMsg().toStdString();
    ASSERT_EQ(path->cm.vn, 4);
    EXPECT_EQ(path->cm.vert[1].cP(), vcg::Point3f(1.5f, 0, 0));
    EXPECT_FLOAT_EQ(path->cm.vert[1].cQ(), 0.25f);
    EXPECT_EQ(path->cm.vert[2].cP(), vcg::Point3f(3, 0, 0));
    const pcskeleton::SkeletonTopology t = topologyOfLayer(*path);
    EXPECT_EQ(t.edges, 3);
    EXPECT_EQ(t.tips, 2);
    EXPECT_EQ(selectedVertices(*path), (std::vector<int>{1}));
}

TEST_F(SkeletonEditFilterTest, SettingTheRadiusChangesQualityAndAttribute) {
    MeshModel* path = addPathSkeleton();
    select(*path, {0, 4});
    QAction* a = action(kRadiusFilter);
    RichParameterList parameters = defaults(a);
    EXPECT_FLOAT_EQ(parameters.getFloat("radius"), 0.3f);  // mean of 0.1 and 0.5
    parameters.setValue("radius", FloatValue(0.7f));
    ASSERT_TRUE(apply(a, parameters)) << plugin->errorMsg().toStdString();
    auto radius = Allocator::FindPerVertexAttribute<float>(path->cm, "pcs_radius");
    ASSERT_TRUE(Allocator::IsValidHandle(path->cm, radius));
    for (int i = 0; i < 5; ++i) {
        const float expected = (i == 0 || i == 4) ? 0.7f : 0.1f * (i + 1);
        EXPECT_FLOAT_EQ(path->cm.vert[i].cQ(), expected) << "node " << i;
        EXPECT_FLOAT_EQ(radius[i], expected) << "node " << i;
    }
}

// A skeleton read from a format without radii (.cg) has zero quality: an edit fills them
// from the neighbours instead of refusing the layer.
TEST_F(SkeletonEditFilterTest, MissingRadiiAreFilledOnTheFirstEdit) {
    MeshModel* path = addPathSkeleton();
    for (auto& v : path->cm.vert) v.Q() = 0;
    select(*path, {2});
    ASSERT_TRUE(applyDefaults(kDeleteFilter)) << plugin->errorMsg().toStdString();
    ASSERT_EQ(path->cm.vn, 4);
    for (const auto& v : path->cm.vert) EXPECT_FLOAT_EQ(v.cQ(), 0.5f);  // half the unit bone length
}

TEST_F(SkeletonEditFilterTest, RefusalsExplainAndLeaveTheLayerAlone) {
    MeshModel* path = addPathSkeleton();
    const auto refused = [&](const char* filter, const RichParameterList& parameters, const char* reason) {
        const auto before = positionsOf(*path);
        const int edges = path->cm.en;
        EXPECT_FALSE(apply(action(filter), parameters)) << filter;
        EXPECT_NE(plugin->errorMsg().indexOf(reason), -1) << filter << ": " << plugin->errorMsg().toStdString();
        EXPECT_EQ(positionsOf(*path), before) << filter;
        EXPECT_EQ(path->cm.en, edges) << filter;
    };
    select(*path, {});
    refused(kDeleteFilter, defaults(action(kDeleteFilter)), "No node");
    select(*path, {0, 1, 2});
    refused(kConnectFilter, defaults(action(kConnectFilter)), "exactly two nodes (3 selected)");
    select(*path, {1, 2});
    refused(kConnectFilter, defaults(action(kConnectFilter)), "already connected");
    select(*path, {3});
    refused(kMergeFilter, defaults(action(kMergeFilter)), "at least 2 nodes");
    RichParameterList zeroRadius = defaults(action(kRadiusFilter));
    zeroRadius.setValue("radius", FloatValue(0.0f));
    refused(kRadiusFilter, zeroRadius, "positive");

    addPointLayer(pcskeleton::shapes::sphere(200, 1.0), "cloud");
    select(*document.mm(), {0, 1});
    EXPECT_FALSE(applyDefaults(kMergeFilter));
    EXPECT_NE(plugin->errorMsg().indexOf("not a skeleton"), -1) << plugin->errorMsg().toStdString();
    EXPECT_EQ(document.mm()->cm.vn, 200);
}
