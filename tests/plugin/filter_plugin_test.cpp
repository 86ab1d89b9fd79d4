// The contraction filter through the real plugin .so.
#include "plugin_fixture.h"

#include "support/sampled_shapes.h"

#include <pcskeleton/version.h>

#include <QCoreApplication>

#include <cmath>
#include <limits>


TEST_F(FilterPluginTest, DeclaresAPointSetFilterThatMeshLabAccepts) {
    QAction* contract = action(kContractFilter);
    ASSERT_NE(contract, nullptr);
    EXPECT_EQ(plugin->getClass(contract), MeshFilterInterface::PointSet);
    EXPECT_EQ(plugin->filterArity(contract), MeshFilterInterface::SINGLE_MESH);
    EXPECT_EQ(plugin->getPreConditions(contract), int(MeshModel::MM_VERTCOORD));
    EXPECT_TRUE(plugin->filterInfo(contract).contains("Laplacian-Based Contraction"));
    addPointLayer(pcskeleton::shapes::sphere(100, 1.0), "sphere");
    const RichParameterList parameters = defaults(contract);
    for (const char* name : {"k", "contractionWeight", "attractionWeight", "contractionScale", "maxContractionWeight",
                             "maxAttractionWeight", "laplacianRowLimit", "maxIterations", "terminationThreshold",
                             "iterationsToRun", "keepEveryIteration"}) {
        ASSERT_TRUE(parameters.hasParameter(name)) << name;
        EXPECT_FALSE(parameters.getParameterByName(name).toolTip().isEmpty()) << name << " has no help text";
    }
    EXPECT_FLOAT_EQ(parameters.getFloat("contractionScale"), 3.0f);
    EXPECT_EQ(parameters.getInt("maxIterations"), 20);
}

// MeshLab 2020.09's Help > Plugin Info shows each filter's description and nothing else.
TEST_F(FilterPluginTest, EveryFilterDescriptionEndsWithTheVersion) {
    ASSERT_GE(plugin->actions().size(), 10);
    for (QAction* filter : plugin->actions()) {
        EXPECT_TRUE(plugin->filterInfo(filter).endsWith("<br><br>pcskeleton " PCSKELETON_VERSION))
            << filter->text().toStdString();
    }
}

TEST_F(FilterPluginTest, ContractsATorusIntoANewLayerLeavingTheInputAlone) {
    const double R = 1.0, r = 0.25;
    MeshModel* input = addPointLayer(pcskeleton::shapes::torus(4000, R, r), "torus");
    const auto before = positionsOf(*input);
    QAction* contract = action(kContractFilter);
    ASSERT_TRUE(apply(contract, defaults(contract))) << plugin->errorMsg().toStdString();

    ASSERT_EQ(document.meshList.size(), 2);
    MeshModel* output = document.mm();
    ASSERT_NE(output, input);
    EXPECT_EQ(output->label(), "torus contracted");
    EXPECT_EQ(positionsOf(*input), before) << "the input layer was modified";
    ASSERT_EQ(output->cm.vn, input->cm.vn);
    EXPECT_EQ(output->cm.fn, 0);

    double distanceBefore = 0, distanceAfter = 0;
    for (int i = 0; i < input->cm.vn; ++i) {
        auto toCircle = [&](const vcg::Point3f& p) { return std::hypot(std::hypot(p[0], p[1]) - R, double(p[2])); };
        distanceBefore += toCircle(input->cm.vert[i].cP());
        distanceAfter += toCircle(output->cm.vert[i].cP());
    }
    EXPECT_LT(distanceAfter, 0.2 * distanceBefore);

    auto index = vcg::tri::Allocator<CMeshO>::FindPerVertexAttribute<int>(output->cm, "pcs_input_index");
    ASSERT_TRUE(vcg::tri::Allocator<CMeshO>::IsValidHandle(output->cm, index));
    EXPECT_EQ(index[output->cm.vert.size() - 1], input->cm.vn - 1);
    EXPECT_GT(progressCalls, 3);
}

TEST_F(FilterPluginTest, RunsTheRequestedIterationsOneLayerEach) {
    addPointLayer(pcskeleton::shapes::cylinder(2000, 0.1, 1.0, true), "tube");
    QAction* contract = action(kContractFilter);
    RichParameterList parameters = defaults(contract);
    parameters.setValue("iterationsToRun", IntValue(2));
    parameters.setValue("keepEveryIteration", BoolValue(true));
    ASSERT_TRUE(apply(contract, parameters)) << plugin->errorMsg().toStdString();
    ASSERT_EQ(document.meshList.size(), 3);
    EXPECT_EQ(document.meshList[1]->label(), "tube contracted (iteration 1)");
    EXPECT_EQ(document.meshList[2]->label(), "tube contracted (iteration 2)");
}

TEST_F(FilterPluginTest, MeshFacesAreIgnored) {
    // A polygon soup: the vertices of a mesh with arbitrary, even nonsensical, faces.
    MeshModel* soup = addPointLayer(pcskeleton::shapes::cylinder(2000, 0.1, 1.0, true), "soup");
    for (int f = 0; f + 2 < soup->cm.vn; f += 3) {
        vcg::tri::Allocator<CMeshO>::AddFace(soup->cm, &soup->cm.vert[f], &soup->cm.vert[f + 1], &soup->cm.vert[f + 2]);
    }
    const int faces = soup->cm.fn;
    QAction* contract = action(kContractFilter);
    ASSERT_TRUE(apply(contract, defaults(contract))) << plugin->errorMsg().toStdString();
    EXPECT_EQ(document.mm()->cm.vn, soup->cm.vn);
    EXPECT_EQ(soup->cm.fn, faces);
}

TEST_F(FilterPluginTest, DeletedVerticesAreSkipped) {
    MeshModel* input = addPointLayer(pcskeleton::shapes::torus(2000, 1.0, 0.3), "torus");
    for (int i = 0; i < 100; ++i) vcg::tri::Allocator<CMeshO>::DeleteVertex(input->cm, input->cm.vert[i * 7]);
    QAction* contract = action(kContractFilter);
    ASSERT_TRUE(apply(contract, defaults(contract))) << plugin->errorMsg().toStdString();
    EXPECT_EQ(document.mm()->cm.vn, 1900);
}

TEST_F(FilterPluginTest, BadInputGivesAClearErrorAndNoLayer) {
    QAction* contract = action(kContractFilter);
    struct Case {
        const char* name;
        pcskeleton::PointList points;
        const char* expected;
    };
    pcskeleton::PointList withNaN = pcskeleton::shapes::sphere(500, 1.0);
    withNaN[3].x() = std::numeric_limits<double>::quiet_NaN();
    pcskeleton::PointList line;
    for (int i = 0; i < 50; ++i) line.emplace_back(i, 0, 0);
    const std::vector<Case> cases = {
        {"empty", {}, "empty"},
        {"few", pcskeleton::shapes::sphere(5, 1.0), "Too few points"},
        {"nan", withNaN, "NaN"},
        {"line", line, "straight line"},
        {"duplicates", pcskeleton::PointList(40, pcskeleton::Point(1, 1, 1)), "Too few points"},
    };
    for (const Case& c : cases) {
        MeshDocument fresh;
        MeshModel* m = fresh.addNewMesh("", c.name, true);
        vcg::tri::Allocator<CMeshO>::AddVertices(m->cm, c.points.size());
        for (std::size_t i = 0; i < c.points.size(); ++i)
            m->cm.vert[i].P() = CMeshO::CoordType(c.points[i].x(), c.points[i].y(), c.points[i].z());
        const auto before = positionsOf(*m);
        RichParameterList parameters;
        plugin->initParameterSet(contract, fresh, parameters);
        EXPECT_FALSE(plugin->applyFilter(contract, fresh, parameters, nullptr)) << c.name;
        EXPECT_TRUE(plugin->errorMsg().contains(c.expected)) << c.name << ": " << plugin->errorMsg().toStdString();
        EXPECT_EQ(fresh.meshList.size(), 1) << c.name;
        if (c.name != std::string("nan")) EXPECT_EQ(positionsOf(*m), before) << c.name;
    }
}

int main(int argc, char** argv) {
    QCoreApplication application(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
