#include "shortcut_lease.h"

#include <QAction>
#include <QSet>
#include <QWidget>

namespace pcskeleton::edit {

void ShortcutLease::take(QWidget* window, const QList<QKeySequence>& keys) {
    if (!window) return;
    // Filter actions belong to their plugins, not to the window: they are found through the
    // menus and toolbars that show them.
    QSet<QAction*> actions;
    for (QAction* action : window->findChildren<QAction*>()) actions.insert(action);
    for (QWidget* widget : window->findChildren<QWidget*>()) {
        for (QAction* action : widget->actions()) actions.insert(action);
    }
    for (QAction* action : actions) {
        if (!action->shortcut().isEmpty() && keys.contains(action->shortcut())) {
            taken_.append({action, action->shortcut()});
            action->setShortcut(QKeySequence());
        }
    }
}

void ShortcutLease::giveBack() {
    for (const auto& [action, key] : taken_) action->setShortcut(key);
    taken_.clear();
}

}  // namespace pcskeleton::edit
