// "Reconstruct Surface from Skeleton" through the real plugin .so: the paper's Fig. 1
// workflow (a scan with missing data gives a skeleton without its loop; reconnecting the
// skeleton gives the surface its handle back), the layer defaults, and refusals.
#include "plugin_fixture.h"

#include <vcg/complex/append.h>

#include "support/sampled_shapes.h"

#include <map>

namespace {

constexpr double kPi = 3.14159265358979323846;

using Allocator = vcg::tri::Allocator<CMeshO>;

struct LayerSurface {
    int faces = 0, boundaryEdges = 0, nonManifoldEdges = 0, eulerCharacteristic = 0;
};

LayerSurface surfaceOf(const MeshModel& m) {
    std::map<std::pair<int, int>, int> uses;
    LayerSurface s;
    for (const auto& f : m.cm.face) {
        if (f.IsD()) continue;
        ++s.faces;
        for (int c = 0; c < 3; ++c) {
            const int a = int(vcg::tri::Index(m.cm, f.cV(c))), b = int(vcg::tri::Index(m.cm, f.cV((c + 1) % 3)));
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    }
    for (const auto& [edge, count] : uses) {
        s.boundaryEdges += count == 1;
        s.nonManifoldEdges += count > 2;
    }
    s.eulerCharacteristic = m.cm.vn - int(uses.size()) + s.faces;
    return s;
}

class ReconstructionFilterTest : public FilterPluginTest {
protected:
    MeshModel* addTorusScan() {
        return addPointLayer(pcskeleton::shapes::withoutSector(pcskeleton::shapes::torus(6000, 1.0, 0.3, 5),
                                                               pcskeleton::Point::Zero(), 0.0, 0.2 * 2 * kPi),
                             "torus scan");
    }

    MeshModel* computeSkeleton() {
        RichParameterList parameters = defaults(action(kSkeletonFilter));
        parameters.setValue("addSegmentsLayer", BoolValue(false));
        EXPECT_TRUE(apply(action(kSkeletonFilter), parameters)) << plugin->errorMsg().toStdString();
        return document.mm();
    }

    // Reconstructs with the dialog's defaults (the current layers) at a test-sized grid.
    MeshModel* reconstruct() {
        RichParameterList parameters = defaults(action(kReconstructFilter));
        parameters.setValue("resolution", IntValue(64));
        if (!apply(action(kReconstructFilter), parameters)) return nullptr;
        return document.mm();
    }

    std::string reconstructionError(MeshModel* points, MeshModel* skeleton) {
        RichParameterList parameters = defaults(action(kReconstructFilter));
        parameters.setValue("pointsLayer", MeshValue(points));
        parameters.setValue("skeletonLayer", MeshValue(skeleton));
        parameters.setValue("resolution", IntValue(32));
        const int layers = document.meshList.size();
        EXPECT_FALSE(apply(action(kReconstructFilter), parameters));
        EXPECT_EQ(document.meshList.size(), layers) << "a refused reconstruction adds no layer";
        return plugin->errorMsg().toStdString();
    }
};

void selectTips(MeshModel& skeleton) {
    std::vector<int> degree(skeleton.cm.vert.size(), 0);
    for (const auto& e : skeleton.cm.edge) {
        ++degree[vcg::tri::Index(skeleton.cm, e.cV(0))];
        ++degree[vcg::tri::Index(skeleton.cm, e.cV(1))];
    }
    for (std::size_t i = 0; i < degree.size(); ++i) {
        skeleton.cm.vert[i].ClearS();
        if (degree[i] == 1) skeleton.cm.vert[i].SetS();
    }
}

}  // namespace

TEST_F(ReconstructionFilterTest, DeclaredWithTwoLayersAndHelpText) {
    addTorusScan();
    QAction* a = action(kReconstructFilter);
    ASSERT_NE(a, nullptr);
    EXPECT_EQ(plugin->filterArity(a), MeshFilterInterface::FIXED);
    EXPECT_TRUE(plugin->getClass(a) & MeshFilterInterface::Remeshing) << "listed with MeshLab's reconstructions";
    EXPECT_TRUE(plugin->getClass(a) & MeshFilterInterface::PointSet);
    const RichParameterList parameters = defaults(a);
    for (const char* name : {"pointsLayer", "skeletonLayer", "resolution", "smoothWeight", "surfaceWeight",
                             "skeletonWeight", "outsideWeight", "outsideRadii", "keepSkeletonTopology", "adaptToNoise",
                             "fitVerticesToPoints"})
        EXPECT_TRUE(parameters.hasParameter(name)) << name;
    for (const RichParameter& p : parameters) EXPECT_FALSE(p.toolTip().isEmpty()) << p.name().toStdString();
    EXPECT_EQ(parameters.getInt("resolution"), 128);
    EXPECT_FLOAT_EQ(parameters.getFloat("surfaceWeight"), 5.0f);
    EXPECT_FLOAT_EQ(parameters.getFloat("outsideRadii"), 4.0f);
    EXPECT_TRUE(parameters.getBool("adaptToNoise")) << "noisy points weigh less by default";
    EXPECT_TRUE(parameters.getBool("fitVerticesToPoints")) << "the vertices are fitted to the points by default";
}

// Paper Fig. 1: the scan's skeleton misses the loop, so does the surface; connecting the
// skeleton's two tips gives a genus-1 surface.
TEST_F(ReconstructionFilterTest, RepairingTheSkeletonRepairsTheSurfaceTopology) {
    MeshModel* scan = addTorusScan();
    const std::vector<vcg::Point3f> scanBefore = positionsOf(*scan);
    MeshModel* skeleton = computeSkeleton();
    ASSERT_NE(skeleton, scan);
    ASSERT_EQ(topologyOfLayer(*skeleton).cycles, 0);
    ASSERT_EQ(topologyOfLayer(*skeleton).tips, 2);

    // The skeleton layer is current: the defaults are it and the points it came from.
    const RichParameterList parameters = defaults(action(kReconstructFilter));
    EXPECT_EQ(parameters.getMesh("pointsLayer"), scan);
    EXPECT_EQ(parameters.getMesh("skeletonLayer"), skeleton);

    MeshModel* open = reconstruct();
    ASSERT_NE(open, nullptr) << plugin->errorMsg().toStdString();
    EXPECT_EQ(open->label(), "torus scan reconstruction");
    EXPECT_GT(progressCalls, 3);
    LayerSurface surface = surfaceOf(*open);
    EXPECT_GT(surface.faces, 1000);
    EXPECT_EQ(surface.boundaryEdges, 0);
    EXPECT_EQ(surface.nonManifoldEdges, 0);
    EXPECT_EQ(surface.eulerCharacteristic, 2) << "genus 0: the missing band is closed off";

    document.setCurrentMesh(skeleton->id());
    selectTips(*skeleton);
    ASSERT_TRUE(apply(action(kConnectFilter), defaults(action(kConnectFilter)))) << plugin->errorMsg().toStdString();
    ASSERT_EQ(topologyOfLayer(*skeleton).cycles, 1);
    const std::vector<vcg::Point3f> skeletonBefore = positionsOf(*skeleton);

    MeshModel* repaired = reconstruct();
    ASSERT_NE(repaired, nullptr) << plugin->errorMsg().toStdString();
    surface = surfaceOf(*repaired);
    EXPECT_EQ(surface.boundaryEdges, 0);
    EXPECT_EQ(surface.nonManifoldEdges, 0);
    EXPECT_EQ(surface.eulerCharacteristic, 0) << "genus 1: the skeleton's loop bridges the band";

    EXPECT_EQ(positionsOf(*scan), scanBefore) << "the points layer is never modified";
    EXPECT_EQ(positionsOf(*skeleton), skeletonBefore) << "nor the skeleton layer";
    EXPECT_EQ(scan->cm.fn, 0);
}

TEST_F(ReconstructionFilterTest, RefusesLayersThatCannotWork) {
    MeshModel* scan = addTorusScan();
    MeshModel* skeleton = computeSkeleton();

    MeshModel* empty = document.addNewMesh("", "empty", false);
    EXPECT_NE(reconstructionError(scan, empty).find("'empty' is empty"), std::string::npos);
    EXPECT_NE(reconstructionError(scan, scan).find("two different layers"), std::string::npos);
    EXPECT_NE(reconstructionError(skeleton, skeleton).find("two different layers"), std::string::npos);
    MeshModel* otherSkeleton = document.addNewMesh("", "copy", false);
    otherSkeleton->cm.Tr = skeleton->cm.Tr;
    vcg::tri::Append<CMeshO, CMeshO>::MeshCopy(otherSkeleton->cm, skeleton->cm);
    EXPECT_NE(reconstructionError(otherSkeleton, skeleton).find("is a skeleton, not a point cloud"), std::string::npos);

    // Radii of zero (a skeleton file without them) and a skeleton somewhere else.
    MeshModel* flat = document.addNewMesh("", "flat", false);
    vcg::tri::Append<CMeshO, CMeshO>::MeshCopy(flat->cm, skeleton->cm);
    for (auto& v : flat->cm.vert) v.Q() = 0;
    auto radius = Allocator::FindPerVertexAttribute<float>(flat->cm, "pcs_radius");
    if (Allocator::IsValidHandle(flat->cm, radius))
        for (auto& v : flat->cm.vert) radius[v] = 0;
    EXPECT_NE(reconstructionError(scan, flat).find("have no radius"), std::string::npos);
    MeshModel* far = document.addNewMesh("", "far", false);
    vcg::tri::Append<CMeshO, CMeshO>::MeshCopy(far->cm, skeleton->cm);
    for (auto& v : far->cm.vert) v.P() += vcg::Point3f(20, 0, 0);
    EXPECT_NE(reconstructionError(scan, far).find("does not describe these points"), std::string::npos);
}
