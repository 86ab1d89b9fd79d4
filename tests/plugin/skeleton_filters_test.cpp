// The skeleton filters through the real plugin .so: full pipeline, thinning of a
// contracted layer, export and re-import, and the errors users see.
#include "plugin_fixture.h"

#include "support/sampled_shapes.h"
#include "support/scan_simulation.h"
#include <pcskeleton/curve_skeleton.h>
#include <pcskeleton/io/point_cloud_io.h>
#include <pcskeleton/io/skeleton_io.h>

#include <QFile>

#include <cstdlib>
#include <unistd.h>

namespace {

using SkeletonFilterTest = FilterPluginTest;

std::string temporaryDirectory() {
    char pattern[] = "/tmp/pcskeleton_plugin_XXXXXX";
    return mkdtemp(pattern);
}

}  // namespace

TEST_F(SkeletonFilterTest, DeclaresEveryFilterWithHelpText) {
    addPointLayer(pcskeleton::shapes::sphere(100, 1.0), "sphere");
    for (const char* name : {kSkeletonFilter, kThinningFilter, kExportFilter}) {
        QAction* a = action(name);
        ASSERT_NE(a, nullptr) << name;
        EXPECT_EQ(plugin->getClass(a), MeshFilterInterface::PointSet) << name;
        EXPECT_FALSE(plugin->filterInfo(a).isEmpty()) << name;
        const RichParameterList parameters = defaults(a);
        for (const RichParameter& p : parameters) {
            EXPECT_FALSE(p.toolTip().isEmpty()) << name << ": " << p.name().toStdString() << " has no help text";
        }
    }
    EXPECT_EQ(plugin->filterArity(action(kThinningFilter)), MeshFilterInterface::FIXED);
    EXPECT_FLOAT_EQ(defaults(action(kSkeletonFilter)).getFloat("sampleRadius"), 0.02f);
}

TEST_F(SkeletonFilterTest, TorusGivesAOneCycleSkeletonLayerAndLeavesTheInputAlone) {
    MeshModel* input = addPointLayer(pcskeleton::shapes::torus(4000, 1.0, 0.25), "torus");
    const auto before = positionsOf(*input);
    QAction* a = action(kSkeletonFilter);
    RichParameterList parameters = defaults(a);
    parameters.setValue("addContractedLayer", BoolValue(true));
    ASSERT_TRUE(apply(a, parameters)) << plugin->errorMsg().toStdString();
    EXPECT_EQ(positionsOf(*input), before);
    EXPECT_GT(progressCalls, 3);

    ASSERT_EQ(document.meshList.size(), 4);
    EXPECT_EQ(document.meshList[1]->label(), "torus contracted");
    MeshModel* segments = document.meshList[2];
    MeshModel* skeleton = document.mm();
    EXPECT_EQ(segments->label(), "torus segments");
    EXPECT_EQ(skeleton->label(), "torus skeleton");

    const pcskeleton::SkeletonTopology t = topologyOfLayer(*skeleton);
    EXPECT_EQ(t.cycles, 1) << pcskeleton::describe(t);
    EXPECT_EQ(t.components, 1) << pcskeleton::describe(t);
    EXPECT_EQ(skeleton->cm.fn, 0);
    EXPECT_TRUE(skeleton->hasDataMask(MeshModel::MM_VERTQUALITY));
    for (const auto& v : skeleton->cm.vert) EXPECT_NEAR(v.cQ(), 0.25, 0.05) << "radius of a node";
    // Drawn to stand out: coloured nodes (MeshLab tints the bones with them), lit in its first view.
    ASSERT_TRUE(skeleton->hasDataMask(MeshModel::MM_VERTCOLOR));
    for (const auto& v : skeleton->cm.vert) {
        EXPECT_GT(int(v.cC()[1]), 2 * int(v.cC()[0])) << "a green node";
        EXPECT_FLOAT_EQ(v.cN()[2], 1.0f);
    }

    // Correspondence: per input vertex in the skeleton layer, per point in the segments layer.
    auto correspondence =
        vcg::tri::Allocator<CMeshO>::FindPerMeshAttribute<std::vector<int>>(skeleton->cm, "pcs_correspondence");
    ASSERT_TRUE(vcg::tri::Allocator<CMeshO>::IsValidHandle(skeleton->cm, correspondence));
    ASSERT_EQ(correspondence().size(), input->cm.vert.size());
    auto node = vcg::tri::Allocator<CMeshO>::FindPerVertexAttribute<int>(segments->cm, "pcs_node");
    ASSERT_TRUE(vcg::tri::Allocator<CMeshO>::IsValidHandle(segments->cm, node));
    ASSERT_EQ(segments->cm.vn, input->cm.vn);
    for (int i = 0; i < input->cm.vn; i += 97) {
        const int n = correspondence()[i];
        ASSERT_GE(n, 0);
        ASSERT_LT(n, skeleton->cm.vn);
        EXPECT_EQ(node[i], n);
        EXPECT_LT(vcg::Distance(input->cm.vert[i].cP(), skeleton->cm.vert[n].cP()), 0.5f) << "point " << i;
    }
    EXPECT_TRUE(segments->hasDataMask(MeshModel::MM_VERTCOLOR));
}

TEST_F(SkeletonFilterTest, ThinningAContractedLayerEqualsTheWholePipeline) {
    addPointLayer(pcskeleton::shapes::torus(3000, 1.0, 0.3), "torus");
    QAction* contract = action(kContractFilter);
    ASSERT_TRUE(apply(contract, defaults(contract))) << plugin->errorMsg().toStdString();
    QAction* thin = action(kThinningFilter);
    const RichParameterList parameters = defaults(thin);
    EXPECT_EQ(parameters.getMesh("sourceLayer"), document.meshList[0]) << "the contracted layer's source is proposed";
    ASSERT_TRUE(apply(thin, parameters)) << plugin->errorMsg().toStdString();
    const pcskeleton::SkeletonTopology stepwise = topologyOfLayer(*document.mm());

    MeshDocument oneCall;
    std::swap(document.meshList, oneCall.meshList);  // start again from the torus alone
    document.meshList.clear();
    addPointLayer(pcskeleton::shapes::torus(3000, 1.0, 0.3), "torus");
    QAction* whole = action(kSkeletonFilter);
    ASSERT_TRUE(apply(whole, defaults(whole))) << plugin->errorMsg().toStdString();
    const pcskeleton::SkeletonTopology direct = topologyOfLayer(*document.mm());
    std::swap(document.meshList, oneCall.meshList);

    EXPECT_EQ(stepwise.nodes, direct.nodes);
    EXPECT_EQ(stepwise.edges, direct.edges);
    EXPECT_EQ(stepwise.cycles, 1);
}

TEST_F(SkeletonFilterTest, ExportWritesEdgesAndRadiiThatReadBackAsTheSameGraph) {
    addPointLayer(pcskeleton::shapes::tube({{pcskeleton::Point(0, 0, 0), pcskeleton::Point(1, 0, 0)},
                                            {pcskeleton::Point(0, 0, 0), pcskeleton::Point(0, 1, 0)},
                                            {pcskeleton::Point(0, 0, 0), pcskeleton::Point(-1, -1, 0)}},
                                           0.1, 5000),
                  "tripod");
    QAction* compute = action(kSkeletonFilter);
    ASSERT_TRUE(apply(compute, defaults(compute))) << plugin->errorMsg().toStdString();
    const MeshModel& layer = *document.mm();
    const pcskeleton::SkeletonTopology t = topologyOfLayer(layer);
    EXPECT_EQ(t.tips, 3) << pcskeleton::describe(t);
    EXPECT_EQ(t.junctions, 1) << pcskeleton::describe(t);

    const std::string dir = temporaryDirectory();
    QAction* exporter = action(kExportFilter);
    for (const char* name : {"s.ply", "s.obj", "s.cg"}) {
        RichParameterList parameters = defaults(exporter);
        const std::string path = dir + "/" + name;
        parameters.setValue("fileName", FileValue(QString::fromStdString(path)));
        ASSERT_TRUE(apply(exporter, parameters)) << plugin->errorMsg().toStdString();
        const pcskeleton::SkeletonGraph back = pcskeleton::readSkeleton(path);
        const pcskeleton::SkeletonTopology r = pcskeleton::analyseTopology(back);
        EXPECT_EQ(r.nodes, t.nodes) << name;
        EXPECT_EQ(r.edges, t.edges) << name;
        EXPECT_EQ(r.tips, 3) << name;
        ASSERT_EQ(int(back.nodes.size()), layer.cm.vn) << name;
        for (int n = 0; n < layer.cm.vn; ++n) {
            EXPECT_NEAR(back.nodes[n].x(), layer.cm.vert[n].cP()[0], 1e-6) << name;
            if (std::string(name) == "s.ply") EXPECT_NEAR(back.radii[n], layer.cm.vert[n].cQ(), 1e-6);
        }
    }
    std::system(("rm -rf '" + dir + "'").c_str());
}

TEST_F(SkeletonFilterTest, LayersThatAreNotWhatAFilterNeedsGiveClearErrors) {
    MeshModel* cloud = addPointLayer(pcskeleton::shapes::torus(2000, 1.0, 0.3), "torus");

    QAction* thin = action(kThinningFilter);
    RichParameterList parameters = defaults(thin);
    EXPECT_FALSE(apply(thin, parameters));
    EXPECT_TRUE(plugin->errorMsg().contains("not made by Contract Point Cloud")) << plugin->errorMsg().toStdString();

    QAction* exporter = action(kExportFilter);
    parameters = defaults(exporter);
    parameters.setValue("fileName", FileValue("/tmp/pcskeleton_never_written.ply"));
    EXPECT_FALSE(apply(exporter, parameters));
    EXPECT_TRUE(plugin->errorMsg().contains("not a skeleton")) << plugin->errorMsg().toStdString();
    EXPECT_NE(access("/tmp/pcskeleton_never_written.ply", F_OK), 0);

    // A contracted layer checked against the wrong source.
    QAction* contract = action(kContractFilter);
    ASSERT_TRUE(apply(contract, defaults(contract)));
    MeshModel* other = addPointLayer(pcskeleton::shapes::sphere(300, 1.0), "sphere");
    document.setCurrentMesh(document.meshList[1]->id());
    parameters = defaults(thin);
    parameters.setValue("sourceLayer", MeshValue(other));
    EXPECT_FALSE(apply(thin, parameters));
    EXPECT_TRUE(plugin->errorMsg().contains("does not match") || plugin->errorMsg().contains("lacks"))
        << plugin->errorMsg().toStdString();

    // Export to a file name without a skeleton extension.
    QAction* compute = action(kSkeletonFilter);
    document.setCurrentMesh(cloud->id());
    ASSERT_TRUE(apply(compute, defaults(compute)));
    parameters = defaults(exporter);
    parameters.setValue("fileName", FileValue("/tmp/skeleton.txt"));
    EXPECT_FALSE(apply(exporter, parameters));
    EXPECT_TRUE(plugin->errorMsg().contains(".ply, .obj or .cg")) << plugin->errorMsg().toStdString();
    // torus, contracted, sphere, and the skeleton run's segments and skeleton.
    EXPECT_EQ(document.meshList.size(), 5) << "failed filters add no layer";
}

// A skeleton opened from ring.ply and edited must not be proposed to overwrite ring.ply.
TEST_F(SkeletonFilterTest, ExportNeverProposesAnExistingFile) {
    const std::string dir = temporaryDirectory();
    const QString opened = QString::fromStdString(dir + "/ring.ply");
    QFile(opened).open(QIODevice::WriteOnly);
    MeshModel* skeleton = document.addNewMesh(opened, "ring.ply", true);
    vcg::tri::Allocator<CMeshO>::AddVertices(skeleton->cm, 2);
    vcg::tri::Allocator<CMeshO>::AddEdge(skeleton->cm, 0, 1);
    EXPECT_EQ(defaults(action(kExportFilter)).getSaveFileName("fileName"), QString::fromStdString(dir + "/ring_1.ply"));
    QFile(QString::fromStdString(dir + "/ring_1.ply")).open(QIODevice::WriteOnly);
    EXPECT_EQ(defaults(action(kExportFilter)).getSaveFileName("fileName"), QString::fromStdString(dir + "/ring_2.ply"));
    std::system(("rm -rf '" + dir + "'").c_str());
}

TEST_F(SkeletonFilterTest, ExportNeverWritesOverAnOpenLayerOrAnExistingFileUnlessTold) {
    const std::string dir = temporaryDirectory();
    const QString opened = QString::fromStdString(dir + "/ring.ply");
    QFile file(opened);
    file.open(QIODevice::WriteOnly);
    file.write("the user's file");
    file.close();
    MeshModel* skeleton = document.addNewMesh(opened, "ring.ply", true);
    vcg::tri::Allocator<CMeshO>::AddVertices(skeleton->cm, 2);
    vcg::tri::Allocator<CMeshO>::AddEdge(skeleton->cm, 0, 1);
    QAction* exporter = action(kExportFilter);
    const auto fileText = [](const QString& path) {
        QFile f(path);
        f.open(QIODevice::ReadOnly);
        return f.readAll();
    };

    // The open layer's own file: refused, even when replacing is allowed.
    RichParameterList parameters = defaults(exporter);
    parameters.setValue("fileName", FileValue(opened));
    parameters.setValue("overwrite", BoolValue(true));
    EXPECT_FALSE(apply(exporter, parameters));
    EXPECT_TRUE(plugin->errorMsg().contains("file of the open layer 'ring.ply'")) << plugin->errorMsg().toStdString();
    EXPECT_EQ(fileText(opened), QByteArray("the user's file"));

    // Another existing file: refused unless 'Replace an existing file' is ticked.
    const QString other = QString::fromStdString(dir + "/other.obj");
    QFile(other).open(QIODevice::WriteOnly);
    parameters.setValue("fileName", FileValue(other));
    parameters.setValue("overwrite", BoolValue(false));
    EXPECT_FALSE(apply(exporter, parameters));
    EXPECT_TRUE(plugin->errorMsg().contains("exists already")) << plugin->errorMsg().toStdString();
    EXPECT_TRUE(fileText(other).isEmpty());
    parameters.setValue("overwrite", BoolValue(true));
    EXPECT_TRUE(apply(exporter, parameters)) << plugin->errorMsg().toStdString();
    EXPECT_EQ(pcskeleton::readSkeleton(other.toStdString()).nodeCount(), 2u);

    // An empty name (what the shipped scripts use): next to the data, a name not taken.
    parameters = defaults(exporter);
    parameters.setValue("fileName", FileValue(""));
    EXPECT_TRUE(apply(exporter, parameters)) << plugin->errorMsg().toStdString();
    EXPECT_EQ(pcskeleton::readSkeleton(dir + "/ring_1.ply").nodeCount(), 2u);
    EXPECT_EQ(fileText(opened), QByteArray("the user's file"));
    std::system(("rm -rf '" + dir + "'").c_str());
}

TEST_F(SkeletonFilterTest, LogsTheQualityReportWithItsWarningsAsWarnings) {
    LogCapture capture(plugin);
    addPointLayer(pcskeleton::shapes::torus(4000, 1.0, 0.25), "torus");
    QAction* a = action(kSkeletonFilter);
    ASSERT_TRUE(apply(a, defaults(a))) << plugin->errorMsg().toStdString();
    const QString report = capture.text(GLLogStream::FILTER);
    EXPECT_TRUE(report.contains("quality report")) << report.toStdString();
    EXPECT_TRUE(report.contains("1 cycle, 0 tips")) << report.toStdString();
    EXPECT_TRUE(report.contains("converged")) << report.toStdString();
    EXPECT_TRUE(report.contains("No warnings.")) << report.toStdString();
    EXPECT_TRUE(capture.text(GLLogStream::WARNING).isEmpty());

    // The same cloud stopped after one iteration: the report warns, at warning level.
    RichParameterList oneIteration = defaults(a);
    oneIteration.setValue("maxIterations", IntValue(1));
    document.setCurrentMesh(document.meshList.front()->id());
    ASSERT_TRUE(apply(a, oneIteration)) << plugin->errorMsg().toStdString();
    const QString warnings = capture.text(GLLogStream::WARNING);
    EXPECT_TRUE(warnings.contains("iteration limit")) << warnings.toStdString();
    // The advice names the dialog's fields, and nothing of the report's warning text lands at filter level.
    EXPECT_TRUE(warnings.contains("raise 'Maximum iterations' or 'Contraction scale s_L'")) << warnings.toStdString();
    EXPECT_FALSE(capture.text(GLLogStream::FILTER).contains("Warning:")) << capture.text(GLLogStream::FILTER).toStdString();
}

TEST_F(SkeletonFilterTest, ARefusedParameterIsNamedByItsDialogLabel) {
    addPointLayer(pcskeleton::shapes::torus(2000, 1.0, 0.25), "torus");
    QAction* a = action(kSkeletonFilter);
    RichParameterList p = defaults(a);
    p.setValue("contractionScale", FloatValue(0.5f));
    ASSERT_FALSE(apply(a, p));
    EXPECT_EQ(plugin->errorMsg().toStdString(), "'Contraction scale s_L' must be between 1 and 1000.");

    // Infinity (a script may give it) is refused by name, never computed with.
    p = defaults(a);
    p.setValue("terminationThreshold", FloatValue(std::numeric_limits<float>::infinity()));
    ASSERT_FALSE(apply(a, p));
    EXPECT_NE(plugin->errorMsg().toStdString().find("must be at least 0 and below 1"), std::string::npos)
        << plugin->errorMsg().toStdString();

    p = defaults(a);
    p.setValue("linkLimit", FloatValue(-1.0f));
    ASSERT_FALSE(apply(a, p));
    EXPECT_EQ(plugin->errorMsg().toStdString(),
              "'Stretched-link limit (node spacings)' must be 0 (every link connects, the paper's rule) or a positive "
              "number of node spacings.");
}

// The narrow-loop limits the CLI and the Python module take are in the dialog too, with
// help, and a refusal names them by their labels.
TEST_F(SkeletonFilterTest, NarrowLoopLimitsAreInTheDialog) {
    QAction* a = action(kSkeletonFilter);
    const RichParameterList parameters = defaults(a);
    const pcskeleton::RefinementLimits loops;
    for (const auto& [name, value] : {std::pair{"loopOpening", loops.minOpening}, std::pair{"loopClearance", loops.minClearance}}) {
        ASSERT_TRUE(parameters.hasParameter(name)) << name;
        EXPECT_FLOAT_EQ(parameters.getFloat(name), float(value)) << name;
        EXPECT_FALSE(parameters.getParameterByName(name).fieldDescription().isEmpty()) << name;
    }
    addPointLayer(pcskeleton::shapes::torus(2000, 1.0, 0.25), "torus");
    RichParameterList p = defaults(a);
    p.setValue("loopOpening", FloatValue(-1.0f));
    ASSERT_FALSE(apply(a, p));
    EXPECT_EQ(plugin->errorMsg().toStdString(),
              "'Narrow-loop opening (tube radii)' must be 0 (no loop is opened) or a positive number of tube radii.");
    p = defaults(a);
    p.setValue("loopClearance", FloatValue(2.0f));
    ASSERT_FALSE(apply(a, p));
    EXPECT_EQ(plugin->errorMsg().toStdString(),
              "'Narrow-loop clearance (fraction of radius)' must be a fraction of a bone's radius between 0 and 1.");
}

TEST_F(SkeletonFilterTest, TipExtensionAndRefinementAreParametersWithHelp) {
    QAction* a = action(kSkeletonFilter);
    const RichParameterList parameters = defaults(a);
    ASSERT_TRUE(parameters.hasParameter("extendTips"));
    ASSERT_TRUE(parameters.hasParameter("refine"));
    EXPECT_TRUE(parameters.getBool("extendTips"));
    EXPECT_TRUE(parameters.getBool("refine")) << "on by default since the robustness suite showed it helps";
    EXPECT_FALSE(parameters.getParameterByName("refine").fieldDescription().isEmpty());
    ASSERT_TRUE(parameters.hasParameter("linkLimit"));
    EXPECT_FLOAT_EQ(parameters.getFloat("linkLimit"), 4.0f);
    EXPECT_FALSE(parameters.getParameterByName("linkLimit").fieldDescription().isEmpty());
    ASSERT_TRUE(parameters.hasParameter("gapLimit"));
    EXPECT_FLOAT_EQ(parameters.getFloat("gapLimit"), 8.0f);
    EXPECT_FALSE(parameters.getParameterByName("gapLimit").fieldDescription().isEmpty());

    // Without extension, a capped tube's skeleton is shorter than with it.
    auto length = [&](bool extend) {
        addPointLayer(pcskeleton::shapes::cylinder(4000, 0.1, 1.0, /*capped=*/true), "tube");
        RichParameterList p = defaults(a);
        p.setValue("extendTips", BoolValue(extend));
        EXPECT_TRUE(apply(a, p)) << plugin->errorMsg().toStdString();
        float low = 1e9f, high = -1e9f;
        for (const auto& v : document.mm()->cm.vert) low = std::min(low, v.cP().Z()), high = std::max(high, v.cP().Z());
        return high - low;
    };
    const float paper = length(false), extended = length(true);
    EXPECT_GT(extended, paper + 0.05f);
    EXPECT_NEAR(extended, 1.2f, 0.03f);
}

TEST_F(SkeletonFilterTest, AGapInTheDataIsBridgedUnlessTheGapLimitIsZero) {
    LogCapture capture(plugin);
    pcskeleton::PointList gapped;
    for (const pcskeleton::Point& q : pcskeleton::shapes::cylinder(8000, 0.1, 2.0, /*capped=*/true)) {
        if (q.z() < 0.9 || q.z() > 1.1) gapped.push_back(q);
    }
    MeshModel* input = addPointLayer(gapped, "scan with a gap");
    QAction* a = action(kSkeletonFilter);
    RichParameterList p = defaults(a);
    ASSERT_TRUE(apply(a, p)) << plugin->errorMsg().toStdString();
    EXPECT_EQ(topologyOfLayer(*document.mm()).components, 1);
    const QString log = capture.text(GLLogStream::FILTER);
    EXPECT_TRUE(log.contains("Gaps in the data: 1 bridged")) << log.toStdString();
    // The bridge is marked on the layer, for the editor to draw and the export to write.
    CMeshO& skeleton = document.mm()->cm;
    auto inferred = vcg::tri::Allocator<CMeshO>::FindPerEdgeAttribute<unsigned char>(skeleton, "pcs_inferred");
    ASSERT_TRUE(vcg::tri::Allocator<CMeshO>::IsValidHandle(skeleton, inferred));
    int marked = 0;
    for (std::size_t e = 0; e < skeleton.edge.size(); ++e) marked += inferred[e];
    EXPECT_EQ(marked, 1);

    document.setCurrentMesh(input->id());
    p.setValue("gapLimit", FloatValue(0.0f));
    ASSERT_TRUE(apply(a, p)) << plugin->errorMsg().toStdString();
    EXPECT_EQ(topologyOfLayer(*document.mm()).components, 2);
    EXPECT_TRUE(capture.text(GLLogStream::FILTER).contains("Gaps in the data: off."));
}

// bench_robustness's figure eight with 5% outliers: two loops go round their own points, not
// holes. Refinement opens them and the log counts them; with Refine unticked the log warns.
TEST_F(SkeletonFilterTest, ALoopOverDataIsOpenedAndCountedOrWarnedOf) {
    LogCapture capture(plugin);
    const pcskeleton::PointList scan =
        pcskeleton::readPointCloud(std::string(PCSKELETON_SCANS_DIR) + "/genus2_outliers5_6300.ply");
    MeshModel* input = addPointLayer(scan, "figure eight with outliers");
    QAction* a = action(kSkeletonFilter);
    RichParameterList p = defaults(a);
    ASSERT_TRUE(apply(a, p)) << plugin->errorMsg().toStdString();
    EXPECT_EQ(topologyOfLayer(*document.mm()).cycles, 2);
    const QString log = capture.text(GLLogStream::FILTER);
    EXPECT_TRUE(log.contains(", 2 loops over data,")) << log.toStdString();
    EXPECT_FALSE(capture.text(GLLogStream::WARNING).contains("rather than a hole"));

    document.setCurrentMesh(input->id());
    p.setValue("refine", BoolValue(false));
    ASSERT_TRUE(apply(a, p)) << plugin->errorMsg().toStdString();
    const QString warnings = capture.text(GLLogStream::WARNING);
    EXPECT_TRUE(warnings.contains("go round points rather than a hole")) << warnings.toStdString();
}

// Over 5% of the points set aside, the warning's advice names thresholds the dialog leaves
// out: it says where they are set instead of sending the user to a field that is not there.
TEST_F(SkeletonFilterTest, AdviceNamingAThresholdOutsideTheDialogSaysWhereItIsSet) {
    LogCapture capture(plugin);
    // 30 tight clumps of 10 points above the torus, each under 1% of the cloud: outlier clusters (7%).
    pcskeleton::PointList cloud = pcskeleton::shapes::torus(4000, 1.0, 0.3);
    for (int clump = 0; clump < 30; ++clump) {
        const double angle = 2 * 3.14159265358979 * clump / 30;
        for (int i = 0; i < 10; ++i)
            cloud.emplace_back(1.5 * std::cos(angle) + 0.002 * i, 1.5 * std::sin(angle), 1.0 + 0.003 * (i % 3));
    }
    addPointLayer(cloud, "scan");
    QAction* a = action(kSkeletonFilter);
    ASSERT_TRUE(apply(a, defaults(a))) << plugin->errorMsg().toStdString();
    const QString log = capture.text(GLLogStream::WARNING);
    EXPECT_TRUE(log.contains("300 points (7%) were set aside as outliers")) << log.toStdString();
    EXPECT_TRUE(log.contains("Raise 'Outlier isolation (spacings)' (not in this dialog: pcskeleton --outlier-isolation, "
                             "or the Python module)"))
        << log.toStdString();
    EXPECT_TRUE(log.contains("or turn off 'Detect outliers'")) << log.toStdString();
}

TEST_F(SkeletonFilterTest, OutliersGetNoNodeUnlessThePapersPipelineIsAsked) {
    LogCapture capture(plugin);
    const pcskeleton::PointList torus = pcskeleton::shapes::torus(4000, 1.0, 0.3);
    const pcskeleton::PointList cloud = pcskeleton::shapes::withOutliers(torus, 0.03, 5);
    MeshModel* input = addPointLayer(cloud, "scan");
    QAction* a = action(kSkeletonFilter);
    RichParameterList p = defaults(a);
    ASSERT_TRUE(p.getBool("detectOutliers"));
    ASSERT_FALSE(p.getBool("paperPipeline"));
    ASSERT_TRUE(apply(a, p)) << plugin->errorMsg().toStdString();
    EXPECT_EQ(topologyOfLayer(*document.mm()).cycles, 1);
    ASSERT_EQ(document.meshList.size(), 3);
    MeshModel* segments = document.meshList[1];
    ASSERT_EQ(segments->label(), "scan segments");
    auto node = vcg::tri::Allocator<CMeshO>::FindPerVertexAttribute<int>(segments->cm, "pcs_node");
    ASSERT_TRUE(vcg::tri::Allocator<CMeshO>::IsValidHandle(segments->cm, node));
    int grey = 0, torusWithoutNode = 0;
    for (std::size_t i = 0; i < segments->cm.vert.size(); ++i) {
        if (node[i] < 0) {
            ++grey;
            EXPECT_EQ(segments->cm.vert[i].cC(), vcg::Color4b(vcg::Color4b::Gray));
            torusWithoutNode += i < torus.size();
        }
    }
    EXPECT_GT(grey, 40) << "most of the 120 outliers are far from the torus";
    EXPECT_EQ(torusWithoutNode, 0);
    const QString log = capture.text(GLLogStream::FILTER);
    EXPECT_TRUE(log.contains(QString("%1 outliers set aside").arg(grey))) << log.toStdString();

    // The paper's pipeline keeps every point: every point has a node.
    document.setCurrentMesh(input->id());
    p.setValue("paperPipeline", BoolValue(true));
    ASSERT_TRUE(apply(a, p)) << plugin->errorMsg().toStdString();
    ASSERT_EQ(document.meshList.size(), 5);
    MeshModel* paperSegments = document.meshList[3];
    auto paperNode = vcg::tri::Allocator<CMeshO>::FindPerVertexAttribute<int>(paperSegments->cm, "pcs_node");
    for (std::size_t i = 0; i < paperSegments->cm.vert.size(); ++i) ASSERT_GE(paperNode[i], 0) << "point " << i;
    EXPECT_TRUE(capture.text(GLLogStream::FILTER).contains("0 outliers set aside"));
    EXPECT_TRUE(capture.text(GLLogStream::FILTER).contains("Tip extension: off"));
}

// A scan in georeferenced coordinates: 1e7 from the origin, 2 across. MeshLab's floats
// merge its points; the filters say so and what to do instead of "too few points".
TEST_F(SkeletonFilterTest, ALayerFarFromTheOriginIsRefusedWithTheReason) {
    pcskeleton::PointList torus = pcskeleton::shapes::torus(2000, 1.0, 0.3);
    for (pcskeleton::Point& p : torus) p += pcskeleton::Point(1e7, 2e6, 0);
    addPointLayer(torus, "far");
    for (const char* filter : {kContractFilter, kSkeletonFilter}) {
        QAction* a = action(filter);
        EXPECT_FALSE(apply(a, defaults(a))) << filter;
        EXPECT_TRUE(plugin->errorMsg().contains("lies 1e+07 from the origin but is only"))
            << plugin->errorMsg().toStdString();
        EXPECT_TRUE(plugin->errorMsg().contains("single precision: that far out, neighbouring values are 1.2 apart")) << plugin->errorMsg().toStdString();
    }
    // 1e3 from the origin is no problem.
    for (pcskeleton::Point& p : torus) p -= pcskeleton::Point(1e7 - 1e3, 2e6, 0);
    addPointLayer(torus, "near");
    QAction* skeleton = action(kSkeletonFilter);
    EXPECT_TRUE(apply(skeleton, defaults(skeleton))) << plugin->errorMsg().toStdString();
}

// A layer of more points than the default subsample is contracted through it: the log says
// so, and every point of the segments layer has its node. "Full resolution" contracts all.
TEST_F(SkeletonFilterTest, LargeLayersAreContractedThroughASubsampleUnlessFullResolution) {
    LogCapture capture(plugin);
    const std::size_t size = pcskeleton::ResolutionParameters{}.maxContractedPoints + 5000;
    MeshModel* input = addPointLayer(pcskeleton::shapes::torus(size, 1.0, 0.3, 21), "big");
    QAction* a = action(kSkeletonFilter);
    RichParameterList p = defaults(a);
    ASSERT_TRUE(p.hasParameter("fullResolution"));
    EXPECT_FALSE(p.getBool("fullResolution"));
    EXPECT_FALSE(p.getParameterByName("fullResolution").fieldDescription().isEmpty());
    ASSERT_TRUE(apply(a, p)) << plugin->errorMsg().toStdString();
    EXPECT_EQ(topologyOfLayer(*document.mm()).cycles, 1);
    const QString log = capture.text(GLLogStream::FILTER);
    EXPECT_TRUE(log.contains(QString("Multi-resolution: ")) && log.contains(QString("of the %1 points contracted").arg(size)))
        << log.toStdString();
    MeshModel* segments = document.meshList[1];
    ASSERT_EQ(segments->cm.vert.size(), size);
    auto node = vcg::tri::Allocator<CMeshO>::FindPerVertexAttribute<int>(segments->cm, "pcs_node");
    ASSERT_TRUE(vcg::tri::Allocator<CMeshO>::IsValidHandle(segments->cm, node));
    for (std::size_t i = 0; i < size; ++i) ASSERT_GE(node[i], 0) << "point " << i;

    document.setCurrentMesh(input->id());
    p.setValue("fullResolution", BoolValue(true));
    LogCapture fullCapture(plugin);
    ASSERT_TRUE(apply(a, p)) << plugin->errorMsg().toStdString();
    EXPECT_EQ(topologyOfLayer(*document.mm()).cycles, 1);
    const QString fullLog = fullCapture.text(GLLogStream::FILTER);
    EXPECT_FALSE(fullLog.contains("Multi-resolution")) << fullLog.toStdString();
    EXPECT_TRUE(fullLog.contains(QString("Input: %1 points in").arg(size))) << fullLog.toStdString();
}
