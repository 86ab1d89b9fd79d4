// The skeleton editor: its screen-space picking and dragging on a known camera, and the
// real edit plugin .so as MeshLab loads it (the interactive part is tests/e2e/gui_edit_test.sh).
#include "../../edit_skeleton/screen_projection.h"

#include <common/interfaces.h>

#include <pcskeleton/version.h>

#include <QApplication>
#include <QPluginLoader>

#include <gtest/gtest.h>

using namespace pcskeleton;
using namespace pcskeleton::edit;

namespace {

// Looking down -z from z = 5 at a 200 x 100 viewport, 90 degrees vertical field of view.
ScreenProjection camera() {
    const double n = 1.0, f = 10.0, aspect = 2.0, t = std::tan(M_PI / 4.0);
    double modelView[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -5, 1};
    double projection[16] = {1 / (aspect * t), 0, 0, 0, 0, 1 / t, 0, 0, 0, 0, -(f + n) / (f - n), -1,
                             0, 0, -2 * f * n / (f - n), 0};
    const int viewport[4] = {0, 0, 200, 100};
    return ScreenProjection::fromGl(modelView, projection, viewport);
}

TEST(ScreenProjection, TheLineOfSightCentreIsTheViewportCentre) {
    const ScreenProjection view = camera();
    const Eigen::Vector3d centre = view.toScreen(Point(0, 0, 0));
    EXPECT_NEAR(centre.x(), 100, 1e-9);
    EXPECT_NEAR(centre.y(), 50, 1e-9);
    // x = 5 at distance 5 is at 45 degrees: the top edge vertically, a quarter across horizontally.
    EXPECT_NEAR(view.toScreen(Point(0, 5, 0)).y(), 100, 1e-9);
    EXPECT_NEAR(view.toScreen(Point(5, 0, 0)).x(), 150, 1e-9);
    EXPECT_TRUE(view.toWorld(view.toScreen(Point(1, 2, -1))).isApprox(Point(1, 2, -1), 1e-9));
}

TEST(ScreenProjection, PicksTheNearestNodeWithinReachAndTheFrontOneAmongEquals) {
    const ScreenProjection view = camera();
    const PointList nodes{Point(0, 0, 0), Point(1, 0, 0), Point(0, 0, 2), Point(0, 0, -2)};
    EXPECT_EQ(nodeAt(view, nodes, {110, 50}, 5), 1);  // node 1 is at x = 110
    EXPECT_EQ(nodeAt(view, nodes, {100, 50}, 5), 2);  // three on the axis: the nearest to the eye
    EXPECT_EQ(nodeAt(view, nodes, {130, 80}, 5), -1);
}

TEST(ScreenProjection, RectangleSelectsWhatItEncloses) {
    const ScreenProjection view = camera();
    const PointList nodes{Point(0, 0, 0), Point(1, 0, 0), Point(-1, 0, 0), Point(0, 1, 0)};
    EXPECT_EQ(nodesInRectangle(view, nodes, {95, 45}, {115, 55}), (std::vector<int>{0, 1}));
    EXPECT_EQ(nodesInRectangle(view, nodes, {115, 55}, {95, 45}), (std::vector<int>{0, 1}));  // any two corners
}

TEST(ScreenProjection, DraggingMovesParallelToTheScreenFollowingTheMouse) {
    const ScreenProjection view = camera();
    const Point anchor(0, 0, 0);
    const Point offset = screenParallelOffset(view, anchor, {100, 50}, {120, 60});
    EXPECT_NEAR(offset.z(), 0.0, 1e-9);
    EXPECT_TRUE(view.toScreen(anchor + offset).head<2>().isApprox(Eigen::Vector2d(120, 60), 1e-9));
}

TEST(EditPlugin, LoadsAsMeshLabDoesAndOffersTheSkeletonTool) {
    QPluginLoader loader(PCSKELETON_EDIT_PLUGIN_PATH);
    auto* factory = qobject_cast<MeshEditInterfaceFactory*>(loader.instance());
    ASSERT_NE(factory, nullptr) << loader.errorString().toStdString();
    ASSERT_EQ(factory->actions().size(), 1);
    QAction* tool = factory->actions().front();
    EXPECT_EQ(tool->text(), "Edit Skeleton");
    EXPECT_TRUE(tool->isCheckable());
    EXPECT_FALSE(tool->icon().isNull());
    EXPECT_NE(factory->getEditToolDescription(tool).indexOf("undo"), -1);
    EXPECT_TRUE(factory->getEditToolDescription(tool).endsWith("pcskeleton " PCSKELETON_VERSION));
    MeshEditInterface* editor = factory->getMeshEditInterface(tool);
    ASSERT_NE(editor, nullptr);
    delete editor;
}

}  // namespace

int main(int argc, char** argv) {
    qputenv("QT_QPA_PLATFORM", "offscreen");  // the factory draws its icon: a GUI application, no screen
    QApplication application(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
