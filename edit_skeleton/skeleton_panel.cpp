#include "skeleton_panel.h"

#include <QCheckBox>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace pcskeleton::edit {

SkeletonPanel::SkeletonPanel(QWidget* parent) : QDockWidget("Edit Skeleton", parent) {
    setObjectName("pcskeletonEditPanel");
    setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);

    counts_ = new QLabel(body);
    counts_->setWordWrap(true);
    selection_ = new QLabel(body);
    layout->addWidget(counts_);
    layout->addWidget(selection_);

    auto* buttons = new QGridLayout();
    delete_ = addButton("Delete", "Del", "Delete the selected nodes and their bones.");
    connect_ = addButton("Connect", "C", "Add a bone between the two selected nodes.");
    disconnect_ = addButton("Disconnect", "D", "Remove the bone between the two selected nodes.");
    merge_ = addButton("Merge", "M", "Replace the selected nodes by one at their centroid, keeping their bones.");
    split_ = addButton("Split", "S", "Insert a node in the middle of the bone between the two selected nodes.");
    radiusUp_ = addButton("Radius +", "+", "Make the selected nodes' radius 10% larger (also Ctrl+wheel).");
    radiusDown_ = addButton("Radius -", "-", "Make the selected nodes' radius 10% smaller (also Ctrl+wheel).");
    undo_ = addButton("Undo", "Ctrl+Z", "Undo the last change.");
    redo_ = addButton("Redo", "Ctrl+Y", "Redo the last undone change.");
    const QList<QPushButton*> ordered{delete_, connect_, disconnect_, merge_, split_, radiusUp_, radiusDown_, undo_, redo_};
    for (int i = 0; i < ordered.size(); ++i) buttons->addWidget(ordered[i], i / 2, i % 2);
    layout->addLayout(buttons);

    reconstruct_ = new QPushButton("Reconstruct from skeleton", this);
    reconstruct_->setFocusPolicy(Qt::NoFocus);
    reconstruct_->setToolTip(
        "Rebuild a closed surface from the points this skeleton was computed from, guided by the skeleton as it "
        "is now (paper Section V; grid of 128 cells, the paper's weights). Adds a mesh layer and leaves both "
        "layers as they are. Other settings: Filters > Point Set > Reconstruct Surface from Skeleton.");
    layout->addWidget(reconstruct_);

    radiusField_ = new QCheckBox("Show radius field (R)", body);
    radiusField_->setFocusPolicy(Qt::NoFocus);
    radiusField_->setToolTip("Draw each bone as a translucent cone and each node as a sphere of its radius.");
    layout->addWidget(radiusField_);

    message_ = new QLabel(body);
    message_->setWordWrap(true);
    layout->addWidget(message_);

    // Below the buttons, which keep their places whatever its length.
    branches_ = new QLabel(body);
    branches_->setWordWrap(true);
    layout->addWidget(branches_);
    hovered_ = new QLabel(body);
    hovered_->setWordWrap(true);
    layout->addWidget(hovered_);

    auto* help = new QLabel(
        "<small>Click a node to select it, Shift+click to add or remove one, drag on empty space to select "
        "in a rectangle, drag a selected node to move the selection parallel to the screen. Right-drag "
        "rotates, the wheel zooms; Esc pauses the tool to use every view control. Edits go into the layer "
        "at once: save it with Filters &gt; Point Set &gt; Export Skeleton.</small>",
        body);
    help->setWordWrap(true);
    layout->addWidget(help);
    layout->addStretch();
    setWidget(body);

    QObject::connect(delete_, &QPushButton::clicked, this, &SkeletonPanel::deleteRequested);
    QObject::connect(connect_, &QPushButton::clicked, this, &SkeletonPanel::connectRequested);
    QObject::connect(disconnect_, &QPushButton::clicked, this, &SkeletonPanel::disconnectRequested);
    QObject::connect(merge_, &QPushButton::clicked, this, &SkeletonPanel::mergeRequested);
    QObject::connect(split_, &QPushButton::clicked, this, &SkeletonPanel::splitRequested);
    QObject::connect(radiusUp_, &QPushButton::clicked, this, [this] { emit radiusScaleRequested(kRadiusStep); });
    QObject::connect(radiusDown_, &QPushButton::clicked, this, [this] { emit radiusScaleRequested(1.0 / kRadiusStep); });
    QObject::connect(undo_, &QPushButton::clicked, this, &SkeletonPanel::undoRequested);
    QObject::connect(redo_, &QPushButton::clicked, this, &SkeletonPanel::redoRequested);
    QObject::connect(reconstruct_, &QPushButton::clicked, this, &SkeletonPanel::reconstructRequested);
    QObject::connect(radiusField_, &QCheckBox::toggled, this, &SkeletonPanel::radiusFieldToggled);
}

QPushButton* SkeletonPanel::addButton(const QString& text, const QString& key, const QString& help) {
    auto* button = new QPushButton(QString("%1 (%2)").arg(text, key), this);
    button->setToolTip(help);
    button->setFocusPolicy(Qt::NoFocus);  // keys keep going to the 3D view
    return button;
}

void SkeletonPanel::showState(const State& state) {
    counts_->setText(state.counts);
    selection_->setText(QString("%1 selected").arg(state.selected));
    branches_->setText(state.branches.isEmpty() ? QString() : "The selection is on " + state.branches + ".");
    hovered_->setText(state.hovered.isEmpty() ? QString() : "Under the cursor: " + state.hovered + ".");
    // Shown only with a text, so that the help below comes back to its place when they empty.
    branches_->setVisible(!state.branches.isEmpty());
    hovered_->setVisible(!state.hovered.isEmpty());
    delete_->setEnabled(state.selected > 0);
    connect_->setEnabled(state.selected == 2 && !state.selectedAreConnected);
    disconnect_->setEnabled(state.selectedAreConnected);
    split_->setEnabled(state.selectedAreConnected);
    merge_->setEnabled(state.selected >= 2);
    radiusUp_->setEnabled(state.selected > 0);
    radiusDown_->setEnabled(state.selected > 0);
    undo_->setEnabled(state.canUndo);
    undo_->setToolTip(state.canUndo ? "Undo: " + state.undoText : "Nothing to undo");
    redo_->setEnabled(state.canRedo);
    redo_->setToolTip(state.canRedo ? "Redo: " + state.redoText : "Nothing to redo");
}

void SkeletonPanel::showMessage(const QString& message, bool isError) {
    message_->setStyleSheet(isError ? "color: #b00020;" : "");
    message_->setText(message);
}

bool SkeletonPanel::radiusFieldShown() const { return radiusField_->isChecked(); }

void SkeletonPanel::toggleRadiusField() { radiusField_->toggle(); }

}  // namespace pcskeleton::edit
