// The editor's dock panel: the skeleton's counts, live; one button per operation with its
// key; the outcome of the last operation; the branch the selection lies on (its order,
// length and radii).
#pragma once

#include <QDockWidget>

class QCheckBox;
class QLabel;
class QPushButton;

namespace pcskeleton::edit {

class SkeletonPanel : public QDockWidget {
    Q_OBJECT
public:
    static constexpr double kRadiusStep = 1.1;  // one radius button, key press or wheel notch

    explicit SkeletonPanel(QWidget* parent);

    struct State {
        QString counts;        // "12 nodes, 11 edges, ..."
        int selected = 0;      // selected nodes
        QString branches;      // the branches the selection lies on ("branch 3: order 2, ...")
        QString hovered;       // the branch of the node under the cursor, or empty
        bool selectedAreConnected = false;  // exactly two selected, joined by a bone
        bool canUndo = false, canRedo = false;
        QString undoText, redoText;
    };
    void showState(const State& state);
    void showMessage(const QString& message, bool isError);
    bool radiusFieldShown() const;
    void toggleRadiusField();

signals:
    void deleteRequested();
    void connectRequested();
    void disconnectRequested();
    void mergeRequested();
    void splitRequested();
    void radiusScaleRequested(double factor);
    void undoRequested();
    void redoRequested();
    void reconstructRequested();
    void radiusFieldToggled();

private:
    QPushButton* addButton(const QString& text, const QString& key, const QString& help);

    QLabel* counts_;
    QLabel* selection_;
    QLabel* message_;
    QLabel* hovered_ = nullptr;
    QLabel* branches_;  // the branches the selection lies on
    QPushButton *delete_, *connect_, *disconnect_, *merge_, *split_, *radiusUp_, *radiusDown_, *undo_, *redo_, *reconstruct_;
    QCheckBox* radiusField_;
};

}  // namespace pcskeleton::edit
