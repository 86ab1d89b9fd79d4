// The real plugin, loaded from its built .so with QPluginLoader and applied to a
// MeshDocument the way MeshLab and meshlabserver use it; shared by the plugin test files.
#pragma once

#include <common/interfaces.h>
#include <common/meshmodel.h>

#include <pcskeleton/contraction/point_cloud_input.h>
#include <pcskeleton/skeleton/skeleton_graph.h>

#include <vcg/complex/allocate.h>

#include <QPluginLoader>

#include <gtest/gtest.h>

// The filters by their menu names, as MeshLab and meshlabserver scripts find them.
inline constexpr const char* kContractFilter = "Contract Point Cloud (Laplacian)";
inline constexpr const char* kSkeletonFilter = "Compute Curve Skeleton (Laplacian Contraction)";
inline constexpr const char* kThinningFilter = "Skeleton from Contracted Points";
inline constexpr const char* kExportFilter = "Export Skeleton (PLY with edges, OBJ, CG)";
inline constexpr const char* kDeleteFilter = "Skeleton: Delete Selected Nodes";
inline constexpr const char* kConnectFilter = "Skeleton: Connect the Two Selected Nodes";
inline constexpr const char* kMergeFilter = "Skeleton: Merge Selected Nodes";
inline constexpr const char* kRadiusFilter = "Skeleton: Set Radius of Selected Nodes";
inline constexpr const char* kReconstructFilter = "Reconstruct Surface from Skeleton";
inline constexpr const char* kBranchesFilter = "Measure Skeleton Branches";

// What the plugin logs while it lives, by level.
struct LogCapture {
    explicit LogCapture(MeshFilterInterface* plugin) : plugin_(plugin) { plugin->setLog(&log); }
    ~LogCapture() { plugin_->setLog(nullptr); }
    QString text(int level) const {
        QString all;
        for (const auto& entry : log.logStringList()) {
            if (entry.first == level) all += entry.second + "\n";
        }
        return all;
    }
    GLLogStream log;
    MeshFilterInterface* plugin_;
};

class FilterPluginTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        loader = new QPluginLoader(PCSKELETON_FILTER_PLUGIN_PATH);
        plugin = qobject_cast<MeshFilterInterface*>(loader->instance());
    }
    static void TearDownTestSuite() {
        loader->unload();
        delete loader;
    }

    void SetUp() override { ASSERT_NE(plugin, nullptr) << loader->errorString().toStdString(); }

    QAction* action(const QString& name) {
        for (QAction* a : plugin->actions())
            if (a->text() == name) return a;
        return nullptr;
    }

    MeshModel* addPointLayer(const pcskeleton::PointList& points, const QString& label) {
        MeshModel* m = document.addNewMesh("", label, true);
        auto v = vcg::tri::Allocator<CMeshO>::AddVertices(m->cm, points.size());
        for (const auto& p : points) (v++)->P() = CMeshO::CoordType(p.x(), p.y(), p.z());
        m->UpdateBoxAndNormals();
        return m;
    }

    RichParameterList defaults(QAction* a) {
        RichParameterList parameters;
        plugin->initParameterSet(a, document, parameters);  // the base's MeshDocument overload
        return parameters;
    }

    bool apply(QAction* a, const RichParameterList& parameters) {
        progressCalls = 0;
        return plugin->applyFilter(a, document, parameters, &countProgress);
    }

    static bool countProgress(const int, const char*) {
        ++progressCalls;
        return true;
    }

    static inline QPluginLoader* loader = nullptr;
    static inline MeshFilterInterface* plugin = nullptr;
    static inline int progressCalls = 0;
    MeshDocument document;
};

inline std::vector<vcg::Point3f> positionsOf(const MeshModel& m) {
    std::vector<vcg::Point3f> positions;
    for (const auto& v : m.cm.vert) positions.push_back(v.cP());
    return positions;
}


inline pcskeleton::SkeletonTopology topologyOfLayer(const MeshModel& m) {
    std::vector<pcskeleton::Edge> edges;
    for (const auto& e : m.cm.edge) {
        edges.push_back({int(vcg::tri::Index(m.cm, e.cV(0))), int(vcg::tri::Index(m.cm, e.cV(1)))});
    }
    return pcskeleton::analyseTopology(m.cm.vert.size(), edges);
}
