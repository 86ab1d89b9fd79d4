#include "edit_skeleton.h"

#include "skeleton_drawing.h"
#include "skeleton_panel.h"

#include <meshlab_layers/meshlab_terms.h>
#include <meshlab_layers/reconstruction_layer.h>
#include <meshlab_layers/skeleton_layer.h>
#include <pcskeleton/io/branch_io.h>

#include <GL/glew.h>

#include <meshlab/glarea.h>
#include <wrap/gl/math.h>
#include <wrap/qt/trackball.h>

#include <QApplication>
#include <QDockWidget>
#include <QMainWindow>
#include <QMessageBox>
#include <QProgressDialog>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace pcskeleton::edit {

namespace {

constexpr double kPickPixels = 10.0;   // how far from a node's centre a click still picks it
constexpr int kDragStartPixels = 3;    // a press moving less than this is a click

}  // namespace

// --- EditSkeletonTool ------------------------------------------------------------------

QString EditSkeletonTool::info() {
    return "Edit a curve skeleton by hand: select, move, delete, connect, merge, split nodes and change their "
           "radius, with undo.";
}

bool EditSkeletonTool::start(MeshModel& m, GLArea* area, MLSceneGLSharedDataContext* context) {
    const QString reason = meshlab::notASkeletonReason(m);
    if (!reason.isEmpty()) {
        // MeshLab drops log lines written here; a message is the only way to say why.
        QMessageBox::information(area, "Edit Skeleton", reason);
        return false;
    }
    SkeletonGraph skeleton = meshlab::readSkeletonLayer(m);
    const int filledRadii = fillMissingRadii(skeleton);
    try {
        editor_ = std::make_unique<SkeletonEditor>(std::move(skeleton));
    } catch (const InvalidInput& e) {
        QMessageBox::information(area, "Edit Skeleton", meshlab::describeForMeshLab(e.problem(), meshlab::editorTerms()));
        return false;
    }
    layer_ = &m;
    area_ = area;
    context_ = context;
    selected_.assign(editor_->graph().nodeCount(), false);
    for (int n : meshlab::selectedNodes(m)) selected_[n] = true;
    sceneDiagonal_ = area->md() ? area->md()->bbox().Diag() : m.cm.bbox.Diag();
    if (!(sceneDiagonal_ > 0)) sceneDiagonal_ = 1.0;

    auto* window = qobject_cast<QMainWindow*>(area->window());
    panel_ = new SkeletonPanel(window);
    if (window) {
        window->addDockWidget(Qt::RightDockWidgetArea, panel_);
        // Sharing the right column with the layer dialog squeezes both: a tab beside it
        // gives the panel the full height.
        for (QDockWidget* dock : window->findChildren<QDockWidget*>()) {
            if (dock != panel_ && dock->isVisible() && window->dockWidgetArea(dock) == Qt::RightDockWidgetArea) {
                window->tabifyDockWidget(dock, panel_);
                break;
            }
        }
    }
    panel_->setVisible(true);
    panel_->raise();
    connect(panel_, &SkeletonPanel::deleteRequested, this, &EditSkeletonTool::deleteSelection);
    connect(panel_, &SkeletonPanel::connectRequested, this, &EditSkeletonTool::connectSelection);
    connect(panel_, &SkeletonPanel::disconnectRequested, this, &EditSkeletonTool::disconnectSelection);
    connect(panel_, &SkeletonPanel::mergeRequested, this, &EditSkeletonTool::mergeSelection);
    connect(panel_, &SkeletonPanel::splitRequested, this, &EditSkeletonTool::splitSelection);
    connect(panel_, &SkeletonPanel::radiusScaleRequested, this, &EditSkeletonTool::scaleSelectionRadius);
    connect(panel_, &SkeletonPanel::undoRequested, this, &EditSkeletonTool::undo);
    connect(panel_, &SkeletonPanel::redoRequested, this, &EditSkeletonTool::redo);
    connect(panel_, &SkeletonPanel::reconstructRequested, this, &EditSkeletonTool::reconstructSurface);
    connect(panel_, &SkeletonPanel::radiusFieldToggled, this, &EditSkeletonTool::redraw);
    // Del is "Delete Selected Faces and Vertices" and Ctrl+Y "fancy lighting" in MeshLab.
    shortcuts_.take(area->window(), {QKeySequence(Qt::Key_Delete), QKeySequence("Ctrl+Z"), QKeySequence("Ctrl+Y"),
                                     QKeySequence("Ctrl+Shift+Z")});
    if (filledRadii > 0) {
        panel_->showMessage(QString("%1 node(s) had no radius and took their neighbours' (saved with the first "
                                    "edit).").arg(filledRadii), false);
    }
    // Moves without a button pressed, so that the panel can name the branch under the cursor.
    hadMouseTracking_ = area->hasMouseTracking();
    area->setMouseTracking(true);
    refreshPanel();
    area->setFocus();
    return true;
}

void EditSkeletonTool::end() {
    shortcuts_.giveBack();
    if (area_) area_->setMouseTracking(hadMouseTracking_);
    hoveredNode_ = -1;
    if (panel_) panel_->deleteLater();
    panel_ = nullptr;
    editor_.reset();
    layer_ = nullptr;
    gesture_ = Gesture::None;
}

std::vector<int> EditSkeletonTool::selection() const {
    std::vector<int> nodes;
    for (std::size_t n = 0; n < selected_.size(); ++n)
        if (selected_[n]) nodes.push_back(static_cast<int>(n));
    return nodes;
}

void EditSkeletonTool::select(const std::vector<int>& nodes, bool add) {
    if (!add) selected_.assign(editor_->graph().nodeCount(), false);
    for (int n : nodes) selected_[n] = add ? !selected_[n] : true;
    meshlab::selectNodes(*layer_, selection());
    if (area_) area_->updateSelection(layer_->id(), true, false);
    refreshPanel();
}

void EditSkeletonTool::apply(const std::function<void()>& operation) {
    if (!editor_) return;
    try {
        operation();
        panel_->showMessage(QString("Done: %1.").arg(QString::fromStdString(editor_->undoText())), false);
        storeInLayer();
    } catch (const InvalidInput& e) {
        panel_->showMessage(meshlab::describeForMeshLab(e.problem(), meshlab::editorTerms()), true);
    } catch (const std::exception& e) {
        panel_->showMessage(QString("Internal error: ") + e.what(), true);
    }
}

void EditSkeletonTool::deleteSelection() {
    apply([this] {
        editor_->deleteNodes(selection());
        selected_.assign(editor_->graph().nodeCount(), false);
    });
}

void EditSkeletonTool::connectSelection() {
    apply([this] {
        const auto [a, b] = exactlyTwoNodes(selection(), "connect nodes");
        editor_->connect(a, b);
    });
}

void EditSkeletonTool::disconnectSelection() {
    apply([this] {
        const auto [a, b] = exactlyTwoNodes(selection(), "remove a bone");
        editor_->deleteEdge(a, b);
    });
}

void EditSkeletonTool::mergeSelection() {
    apply([this] {
        const int merged = editor_->mergeNodes(selection());
        selected_.assign(editor_->graph().nodeCount(), false);
        selected_[merged] = true;
    });
}

void EditSkeletonTool::splitSelection() {
    apply([this] {
        const auto [a, b] = exactlyTwoNodes(selection(), "split a bone");
        const int inserted = editor_->splitEdge(a, b);
        selected_.assign(editor_->graph().nodeCount(), false);
        selected_[inserted] = true;
    });
}

void EditSkeletonTool::scaleSelectionRadius(double factor) {
    apply([this, factor] { editor_->scaleRadius(selection(), factor); });
}

void EditSkeletonTool::undo() { stepHistory(false); }

void EditSkeletonTool::redo() { stepHistory(true); }

void EditSkeletonTool::stepHistory(bool forward) {
    if (!editor_) return;
    if (forward ? !editor_->canRedo() : !editor_->canUndo()) {
        panel_->showMessage(forward ? "Nothing to redo." : "Nothing to undo.", false);
        return;
    }
    const QString what = QString::fromStdString(forward ? editor_->redoText() : editor_->undoText());
    if (forward) editor_->redo();
    else editor_->undo();
    // Indices mean other nodes once nodes came or went: keep the selection only if not.
    if (selected_.size() != editor_->graph().nodeCount()) selected_.assign(editor_->graph().nodeCount(), false);
    panel_->showMessage(QString(forward ? "Redone: %1." : "Undone: %1.").arg(what), false);
    storeInLayer();
}

void EditSkeletonTool::reconstructSurface() {
    MeshDocument* document = area_ ? area_->md() : nullptr;
    if (!document || !layer_) return;
    MeshModel* points = meshlab::sourceLayerOf(*document, *layer_);
    if (!points) points = meshlab::defaultPointsLayer(*document);
    if (!points || points == layer_) {
        panel_->showMessage("Open the point cloud this skeleton belongs to first: the surface passes through its "
                            "points.", true);
        return;
    }
    QProgressDialog progress("Reconstructing the surface...", QString(), 0, 100, area_->window());
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(300);
    const ProgressCallback report = [&progress](int percent, const char* what) {
        progress.setLabelText(what);
        progress.setValue(percent);
        QCoreApplication::processEvents();
    };
    QApplication::setOverrideCursor(Qt::WaitCursor);
    meshlab::ReconstructedLayer result;
    QString failure;
    try {
        // The tool keeps editing the skeleton: the new layer is not made current.
        result = meshlab::addReconstructionLayer(*document, *points, *layer_, ReconstructionParameters{}, report, false);
    } catch (const InvalidInput& e) {
        failure = meshlab::describeForMeshLab(e.problem(), meshlab::editorTerms());
    } catch (const std::bad_alloc&) {
        failure = "Out of memory: use the filter with a lower grid resolution.";
    } catch (const std::exception& e) {
        failure = QString("Internal error: ") + e.what();
    }
    QApplication::restoreOverrideCursor();
    if (!result.layer) {
        panel_->showMessage(failure, true);
        return;
    }
    if (context_) {
        MLRenderingData rendering;
        MLPoliciesStandAloneFunctions::suggestedDefaultPerViewRenderingData(result.layer, rendering);
        context_->setRenderingDataPerMeshView(result.layer->id(), area_->context(), rendering);
        context_->manageBuffers(result.layer->id());
    }
    const ReconstructionReport& r = result.report;
    panel_->showMessage(QString("Added '%1': %2 (%3 s).")
                            .arg(result.layer->label(), QString::fromStdString(describe(r.topology)))
                            .arg(r.setupSeconds + r.solveSeconds + r.extractionSeconds, 0, 'f', 1),
                        !r.topology.closedManifold());
    area_->update();
}

void EditSkeletonTool::storeInLayer() {
    hoveredNode_ = -1;  // nodes may have been renumbered
    meshlab::writeSkeletonLayer(*layer_, editor_->skeleton());
    meshlab::selectNodes(*layer_, selection());
    layer_->setMeshModified(true);  // MeshLab offers to save it on closing
    if (context_) {
        MLRenderingData::RendAtts changed;
        changed[MLRenderingData::ATT_NAMES::ATT_VERTPOSITION] = true;
        changed[MLRenderingData::ATT_NAMES::ATT_VERTNORMAL] = true;
        changed[MLRenderingData::ATT_NAMES::ATT_VERTCOLOR] = true;
        context_->meshAttributesUpdated(layer_->id(), true, changed);
        context_->manageBuffers(layer_->id());
    }
    if (area_) area_->updateSelection(layer_->id(), true, false);
    refreshPanel();
    redraw();
}

void EditSkeletonTool::refreshPanel() {
    if (!panel_ || !editor_) return;
    const SkeletonGraph& g = editor_->graph();
    SkeletonPanel::State state;
    state.counts = QString::fromStdString(describe(analyseTopology(g)));
    const std::vector<int> nodes = selection();
    state.selected = static_cast<int>(nodes.size());
    const bool hovering = hoveredNode_ >= 0 && hoveredNode_ < int(g.nodeCount());
    if (!nodes.empty() || hovering) {
        const SkeletonBranches branches = measureBranches(g);
        if (!nodes.empty()) state.branches = QString::fromStdString(describeBranchesOf(branches, nodes));
        if (hovering) state.hovered = QString::fromStdString(describeBranchesOf(branches, {hoveredNode_}));
    }
    state.selectedAreConnected =
        nodes.size() == 2 && hasEdge(g.edges, nodes[0], nodes[1]);
    state.canUndo = editor_->canUndo();
    state.canRedo = editor_->canRedo();
    state.undoText = QString::fromStdString(editor_->undoText());
    state.redoText = QString::fromStdString(editor_->redoText());
    panel_->showState(state);
}

void EditSkeletonTool::redraw() {
    if (area_) area_->updateAllSiblingsGLAreas();
}

Eigen::Vector2d EditSkeletonTool::toGlWindow(const QPoint& widgetPoint) const {
    const double ratio = area_->devicePixelRatio();
    return {widgetPoint.x() * ratio, (area_->height() - widgetPoint.y()) * ratio};
}

double EditSkeletonTool::markerSize() const { return 0.006 * sceneDiagonal_; }

// --- Mouse, keys, wheel ----------------------------------------------------------------

void EditSkeletonTool::mousePressEvent(QMouseEvent* event, MeshModel&, GLArea* area) {
    if (!editor_) return;
    pressedAt_ = mouseAt_ = event->pos();
    if (event->button() != Qt::LeftButton) {
        // Right-drag rotates and middle-drag pans, as the left and middle buttons do
        // when no tool is active.
        gesture_ = Gesture::Rotating;
        const Qt::MouseButton button = event->button() == Qt::RightButton ? Qt::LeftButton : event->button();
        area->trackball.MouseDown(QT2VCG_X(area, event), QT2VCG_Y(area, event), QT2VCG(button, Qt::NoModifier));
        return;
    }
    if (!view_.valid) return;
    const bool add = event->modifiers() & Qt::ShiftModifier;
    const int node = nodeAt(view_, editor_->graph().nodes, toGlWindow(event->pos()), kPickPixels * area->devicePixelRatio());
    if (node < 0) {
        gesture_ = Gesture::RubberBand;
    } else if (add) {
        select({node}, true);
        gesture_ = Gesture::None;
    } else {
        if (!selected_[node]) select({node}, false);
        pressedNode_ = node;
        gesture_ = Gesture::PressedOnNode;
    }
}

void EditSkeletonTool::mouseMoveEvent(QMouseEvent* event, MeshModel&, GLArea* area) {
    if (!editor_) return;
    mouseAt_ = event->pos();
    switch (gesture_) {
        case Gesture::Rotating: area->trackball.MouseMove(QT2VCG_X(area, event), QT2VCG_Y(area, event)); break;
        case Gesture::PressedOnNode:
            if ((mouseAt_ - pressedAt_).manhattanLength() >= kDragStartPixels) gesture_ = Gesture::Moving;
            break;
        case Gesture::Moving: {
            const std::vector<int> moved = selection();
            Point centroid = Point::Zero();
            for (int n : moved) centroid += editor_->graph().nodes[n];
            centroid /= double(std::max<std::size_t>(moved.size(), 1));
            dragOffset_ = screenParallelOffset(view_, centroid, toGlWindow(pressedAt_), toGlWindow(mouseAt_));
            break;
        }
        case Gesture::None: {
            const int node = view_.valid ? nodeAt(view_, editor_->graph().nodes, toGlWindow(mouseAt_),
                                                   kPickPixels * area->devicePixelRatio())
                                         : -1;
            if (node != hoveredNode_) {
                hoveredNode_ = node;
                refreshPanel();
            }
            break;
        }
        case Gesture::RubberBand: break;
    }
}

void EditSkeletonTool::mouseReleaseEvent(QMouseEvent* event, MeshModel&, GLArea* area) {
    if (!editor_) return;
    const Gesture finished = gesture_;
    gesture_ = Gesture::None;
    switch (finished) {
        case Gesture::Rotating:
            area->trackball.MouseUp(QT2VCG_X(area, event), QT2VCG_Y(area, event), QT2VCG(Qt::LeftButton, Qt::NoModifier));
            break;
        case Gesture::Moving: {
            const Point offset = dragOffset_;
            dragOffset_ = Point::Zero();
            apply([this, offset] { editor_->moveNodes(selection(), offset); });
            break;
        }
        case Gesture::RubberBand: {
            const bool add = event->modifiers() & Qt::ShiftModifier;
            if ((mouseAt_ - pressedAt_).manhattanLength() < kDragStartPixels) {
                if (!add) select({}, false);  // a click on empty space clears the selection
                break;
            }
            std::vector<int> inside =
                nodesInRectangle(view_, editor_->graph().nodes, toGlWindow(pressedAt_), toGlWindow(mouseAt_));
            if (add) {  // add, not toggle
                inside.erase(std::remove_if(inside.begin(), inside.end(), [this](int n) { return bool(selected_[n]); }),
                             inside.end());
            }
            select(inside, add);
            break;
        }
        case Gesture::PressedOnNode:
        case Gesture::None: break;
    }
}

void EditSkeletonTool::keyPressEvent(QKeyEvent* event, MeshModel&, GLArea*) {
    if (!editor_) return;
    const bool control = event->modifiers() & Qt::ControlModifier;
    const bool shift = event->modifiers() & Qt::ShiftModifier;
    event->accept();
    switch (event->key()) {
        case Qt::Key_Delete:
        case Qt::Key_Backspace: deleteSelection(); break;
        case Qt::Key_C: connectSelection(); break;
        case Qt::Key_D: disconnectSelection(); break;
        case Qt::Key_M: mergeSelection(); break;
        case Qt::Key_S: splitSelection(); break;
        case Qt::Key_Plus:
        case Qt::Key_Equal:
        case Qt::Key_PageUp: scaleSelectionRadius(SkeletonPanel::kRadiusStep); break;
        case Qt::Key_Minus:
        case Qt::Key_PageDown: scaleSelectionRadius(1.0 / SkeletonPanel::kRadiusStep); break;
        case Qt::Key_R: panel_->toggleRadiusField(); break;
        case Qt::Key_Z:
            if (control && shift) redo();
            else if (control) undo();
            else event->ignore();
            break;
        case Qt::Key_Y:
            if (control) redo();
            else event->ignore();
            break;
        case Qt::Key_A:
            if (control) {
                std::vector<int> all(editor_->graph().nodeCount());
                std::iota(all.begin(), all.end(), 0);
                select(all, false);
            } else {
                event->ignore();
            }
            break;
        default: event->ignore(); return;
    }
    redraw();
}

void EditSkeletonTool::wheelEvent(QWheelEvent* event, MeshModel&, GLArea* area) {
    if (!editor_) return;
    const float notches = event->angleDelta().y() / 120.0f;
    if (event->modifiers() & Qt::ControlModifier) {
        if (notches != 0.0f) scaleSelectionRadius(notches > 0 ? SkeletonPanel::kRadiusStep : 1.0 / SkeletonPanel::kRadiusStep);
    } else {
        area->trackball.MouseWheel(notches);
    }
}

// --- Drawing ---------------------------------------------------------------------------

void EditSkeletonTool::draw() {
    if (!editor_ || !layer_) return;
    glPushMatrix();
    glMultMatrix(layer_->cm.Tr);
    double modelView[16], projection[16];
    int viewport[4];
    glGetDoublev(GL_MODELVIEW_MATRIX, modelView);
    glGetDoublev(GL_PROJECTION_MATRIX, projection);
    glGetIntegerv(GL_VIEWPORT, viewport);
    view_ = ScreenProjection::fromGl(modelView, projection, viewport);

    PointList nodes = editor_->graph().nodes;
    if (gesture_ == Gesture::Moving) {
        for (int n : selection()) nodes[n] += dragOffset_;
    }
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    // The skeleton lies inside the cloud: it is drawn over it, or it could not be seen.
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    drawBones(editor_->graph(), nodes, selected_);
    drawNodes(nodes, selected_, markerSize());
    if (panel_ && panel_->radiusFieldShown()) drawRadiusField(editor_->graph(), nodes);
    glPopAttrib();
    glPopMatrix();
    if (gesture_ == Gesture::RubberBand) drawRubberBand(*area_, pressedAt_, mouseAt_);
}

}  // namespace pcskeleton::edit
