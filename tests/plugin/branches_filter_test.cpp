// Measure Skeleton Branches through the real plugin .so: a Y's branches logged, its points
// coloured by branch in a new layer, the table written where asked and never over a file
// by surprise, and the refusals users see.
#include "plugin_fixture.h"

#include "support/sampled_shapes.h"

#include <QFile>

#include <cstdlib>
#include <set>

namespace {

using BranchesFilterTest = FilterPluginTest;

// A Y of tubes standing on its stem: 3 branches, the stem from its lowest point.
pcskeleton::PointList standingY() {
    const pcskeleton::Point base(0, 0, 0), fork(0, 0, 1), left(-0.5, 0, 1.5), right(0.6, 0, 1.6);
    return pcskeleton::shapes::tube({{base, fork}, {fork, left}, {fork, right}}, 0.06, 6000);
}

QByteArray fileText(const QString& path) {
    QFile file(path);
    file.open(QIODevice::ReadOnly);
    return file.readAll();
}

}  // namespace

TEST_F(BranchesFilterTest, AYsBranchesAreLoggedAndItsPointsColouredByBranch) {
    LogCapture capture(plugin);
    MeshModel* points = addPointLayer(standingY(), "Y");
    ASSERT_TRUE(apply(action(kSkeletonFilter), defaults(action(kSkeletonFilter)))) << plugin->errorMsg().toStdString();
    MeshModel* skeleton = document.mm();
    const auto pointsBefore = positionsOf(*points);
    const auto skeletonBefore = positionsOf(*skeleton);

    QAction* a = action(kBranchesFilter);
    ASSERT_NE(a, nullptr);
    EXPECT_FALSE(plugin->filterInfo(a).isEmpty());
    for (const RichParameter& p : defaults(a)) EXPECT_FALSE(p.toolTip().isEmpty()) << p.name().toStdString();
    ASSERT_TRUE(apply(a, defaults(a))) << plugin->errorMsg().toStdString();
    const QString log = capture.text(GLLogStream::FILTER);
    EXPECT_TRUE(log.contains("Branches of 'Y skeleton' (up axis +Z): 3 branches (order 1: 2, order 2: 1)"))
        << log.toStdString();
    EXPECT_TRUE(log.contains("  branch 0: order 1, from the root, length ")) << log.toStdString();
    EXPECT_EQ(positionsOf(*points), pointsBefore) << "the points are not changed";
    EXPECT_EQ(positionsOf(*skeleton), skeletonBefore) << "the skeleton is not changed";

    MeshModel* coloured = document.mm();
    ASSERT_NE(coloured, skeleton);
    EXPECT_EQ(coloured->label(), "Y branches");
    ASSERT_EQ(coloured->cm.vn, points->cm.vn);
    EXPECT_TRUE(coloured->hasDataMask(MeshModel::MM_VERTCOLOR));
    auto branch = vcg::tri::Allocator<CMeshO>::FindPerVertexAttribute<int>(coloured->cm, "pcs_branch");
    ASSERT_TRUE(vcg::tri::Allocator<CMeshO>::IsValidHandle(coloured->cm, branch));
    std::set<int> seen;
    for (const auto& v : coloured->cm.vert) {
        EXPECT_GE(branch[v], -1);
        EXPECT_LT(branch[v], 3);
        seen.insert(branch[v]);
    }
    EXPECT_TRUE(seen.count(0) && seen.count(1) && seen.count(2));
    // The stem's foot and the two arms' ends lie in three different branches.
    const auto branchNear = [&](const vcg::Point3f& p) {
        int best = 0;
        for (int i = 1; i < coloured->cm.vn; ++i) {
            if (vcg::Distance(coloured->cm.vert[i].cP(), p) < vcg::Distance(coloured->cm.vert[best].cP(), p)) best = i;
        }
        return branch[best];
    };
    EXPECT_EQ(branchNear(vcg::Point3f(0, 0, 0.1)), 0);
    EXPECT_NE(branchNear(vcg::Point3f(-0.45, 0, 1.45)), branchNear(vcg::Point3f(0.55, 0, 1.55)));
    EXPECT_NE(branchNear(vcg::Point3f(-0.45, 0, 1.45)), 0);
    // The junction's node (above the fork) holds points of both arms: each goes to the branch
    // of the arm it lies along, not all to the stem that reaches the junction.
    auto correspondence =
        vcg::tri::Allocator<CMeshO>::FindPerMeshAttribute<std::vector<int>>(skeleton->cm, "pcs_correspondence");
    ASSERT_TRUE(vcg::tri::Allocator<CMeshO>::IsValidHandle(skeleton->cm, correspondence));
    ASSERT_EQ(correspondence().size(), std::size_t(coloured->cm.vn));
    std::vector<int> degree(std::size_t(skeleton->cm.vn), 0);
    for (const auto& e : skeleton->cm.edge) {
        ++degree[std::size_t(vcg::tri::Index(skeleton->cm, e.cV(0)))], ++degree[std::size_t(vcg::tri::Index(skeleton->cm, e.cV(1)))];
    }
    std::set<int> atJunctions;
    for (int i = 0; i < coloured->cm.vn; ++i) {
        const int n = correspondence()[std::size_t(i)];
        if (n >= 0 && degree[std::size_t(n)] >= 3) atJunctions.insert(branch[i]);
    }
    EXPECT_TRUE(atJunctions.count(1) && atJunctions.count(2)) << "the junction's points are all in branch " << *atJunctions.begin();
}

TEST_F(BranchesFilterTest, TheTableIsWrittenWhereAskedAndAnExistingFileOnlyWhenTold) {
    addPointLayer(standingY(), "Y");
    ASSERT_TRUE(apply(action(kSkeletonFilter), defaults(action(kSkeletonFilter)))) << plugin->errorMsg().toStdString();
    MeshModel* skeleton = document.mm();
    char pattern[] = "/tmp/pcskeleton_branches_XXXXXX";
    const QString dir = mkdtemp(pattern);
    const QString table = dir + "/y_branches.csv";
    QAction* a = action(kBranchesFilter);
    RichParameterList parameters = defaults(a);
    parameters.setValue("tableFile", FileValue(table));
    ASSERT_TRUE(apply(a, parameters)) << plugin->errorMsg().toStdString();
    const QByteArray written = fileText(table);
    EXPECT_TRUE(written.startsWith("branch,parent,order,")) << written.toStdString();
    EXPECT_EQ(written.count('\n'), 4) << "a header and three branches";

    QFile file(table);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write("the user's file");
    file.close();
    document.setCurrentMesh(skeleton->id());
    EXPECT_FALSE(apply(a, parameters));
    EXPECT_TRUE(plugin->errorMsg().contains("exists already")) << plugin->errorMsg().toStdString();
    EXPECT_EQ(fileText(table), QByteArray("the user's file"));
    parameters.setValue("overwrite", BoolValue(true));
    document.setCurrentMesh(skeleton->id());
    ASSERT_TRUE(apply(a, parameters)) << plugin->errorMsg().toStdString();
    EXPECT_EQ(fileText(table), written);

    parameters.setValue("tableFile", FileValue(dir + "/y_branches.txt"));
    document.setCurrentMesh(skeleton->id());
    EXPECT_FALSE(apply(a, parameters));
    EXPECT_TRUE(plugin->errorMsg().contains("must end in .csv or .json")) << plugin->errorMsg().toStdString();
    std::system(("rm -rf '" + dir.toStdString() + "'").c_str());
}

TEST_F(BranchesFilterTest, APointLayerOrARootThatIsNoNodeIsRefused) {
    addPointLayer(standingY(), "Y");
    QAction* a = action(kBranchesFilter);
    EXPECT_FALSE(apply(a, defaults(a)));
    EXPECT_TRUE(plugin->errorMsg().contains("not a skeleton")) << plugin->errorMsg().toStdString();
    ASSERT_TRUE(apply(action(kSkeletonFilter), defaults(action(kSkeletonFilter)))) << plugin->errorMsg().toStdString();
    RichParameterList parameters = defaults(a);
    parameters.setValue("rootNode", IntValue(document.mm()->cm.vn));
    EXPECT_FALSE(apply(a, parameters));
    EXPECT_TRUE(plugin->errorMsg().contains("is not a node of the skeleton")) << plugin->errorMsg().toStdString();
}
