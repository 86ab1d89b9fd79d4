// The skeleton editor on MeshLab's Edit toolbar: picks, drags and draws the nodes of the
// current skeleton layer and applies every change through pcskeleton::SkeletonEditor, so
// each one is checked and can be undone. The layer is rewritten after every change, so
// saving or running a filter sees the edits, and ending the tool keeps them.
#pragma once

#include "screen_projection.h"
#include "shortcut_lease.h"

#include <meshlab_layers/meshlab_compat.h>

#include <pcskeleton/editing/skeleton_editing.h>

#include <QPoint>

#include <functional>
#include <memory>

class QAction;

namespace pcskeleton::edit {

class SkeletonPanel;

class EditSkeletonTool : public QObject, public meshlab::EditToolBase {
    Q_OBJECT
public:
    static QString info();

    // MeshLab's entry points, renamed in 2021.05.
#if PCSKELETON_MESHLAB_2021_API
    bool startEdit(MeshModel& m, GLArea* area, MLSceneGLSharedDataContext* context) override {
        return start(m, area, context);
    }
    void endEdit(MeshModel&, GLArea*, MLSceneGLSharedDataContext*) override { end(); }
    void decorate(MeshModel&, GLArea*, QPainter*) override { draw(); }
#else
    bool StartEdit(MeshModel& m, GLArea* area, MLSceneGLSharedDataContext* context) override {
        return start(m, area, context);
    }
    void EndEdit(MeshModel&, GLArea*, MLSceneGLSharedDataContext*) override { end(); }
    void Decorate(MeshModel&, GLArea*, QPainter*) override { draw(); }
#endif
    void mousePressEvent(QMouseEvent* event, MeshModel& m, GLArea* area) override;
    void mouseMoveEvent(QMouseEvent* event, MeshModel& m, GLArea* area) override;
    void mouseReleaseEvent(QMouseEvent* event, MeshModel& m, GLArea* area) override;
    void keyPressEvent(QKeyEvent* event, MeshModel& m, GLArea* area) override;
    void wheelEvent(QWheelEvent* event, MeshModel& m, GLArea* area) override;

private:
    bool start(MeshModel& m, GLArea* area, MLSceneGLSharedDataContext* context);
    void end();
    void draw();

    enum class Gesture { None, PressedOnNode, Moving, RubberBand, Rotating };

    // Runs an operation of the editor; on refusal shows why and changes nothing.
    void apply(const std::function<void()>& operation);
    void deleteSelection();
    void connectSelection();
    void disconnectSelection();
    void mergeSelection();
    void splitSelection();
    void scaleSelectionRadius(double factor);
    void undo();
    void redo();
    void reconstructSurface();
    void stepHistory(bool forward);

    // Writes the graph and the selection into the layer and refreshes views and panel.
    void storeInLayer();
    void refreshPanel();
    void redraw();
    std::vector<int> selection() const;
    void select(const std::vector<int>& nodes, bool add);
    // A widget position (Qt: logical pixels, y down) in OpenGL window pixels (y up).
    Eigen::Vector2d toGlWindow(const QPoint& widgetPoint) const;
    double markerSize() const;

    MeshModel* layer_ = nullptr;
    GLArea* area_ = nullptr;
    MLSceneGLSharedDataContext* context_ = nullptr;
    std::unique_ptr<SkeletonEditor> editor_;
    std::vector<bool> selected_;
    SkeletonPanel* panel_ = nullptr;
    ShortcutLease shortcuts_;
    ScreenProjection view_;
    double sceneDiagonal_ = 1.0;

    Gesture gesture_ = Gesture::None;
    QPoint pressedAt_, mouseAt_;
    int pressedNode_ = -1;
    int hoveredNode_ = -1;  // the node under the cursor (no button pressed), or -1
    bool hadMouseTracking_ = false;  // the view's, given back at the end
    Point dragOffset_ = Point::Zero();
};

}  // namespace pcskeleton::edit
