// While the Edit Skeleton tool runs, the keys it needs (Delete, C, M, ...) are taken from
// MeshLab's application-wide shortcuts and given back when it ends: otherwise MeshLab's
// own actions would swallow them before the tool sees them.
#pragma once

#include <QKeySequence>
#include <QList>
#include <QPair>

class QAction;
class QWidget;

namespace pcskeleton::edit {

class ShortcutLease {
public:
    void take(QWidget* window, const QList<QKeySequence>& keys);
    void giveBack();

private:
    QList<QPair<QAction*, QKeySequence>> taken_;
};

}  // namespace pcskeleton::edit
