#include "edit_skeleton_factory.h"

#include "edit_skeleton.h"

#include <meshlab_layers/meshlab_terms.h>

#include <QPainter>

namespace {

// A stick figure: yellow nodes joined by blue bones, the tool's look.
QIcon skeletonIcon() {
    QPixmap pixmap(32, 32);
    pixmap.fill(Qt::transparent);
    QPainter p(&pixmap);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(QPen(QColor(40, 90, 255), 3));
    const QPointF hip(16, 18), head(16, 4), leftFoot(7, 29), rightFoot(25, 29), hand(28, 10);
    p.drawLine(hip, head);
    p.drawLine(hip, leftFoot);
    p.drawLine(hip, rightFoot);
    p.drawLine(QPointF(16, 10), hand);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(255, 210, 0));
    for (const QPointF& node : {hip, head, leftFoot, rightFoot, hand}) p.drawEllipse(node, 3.5, 3.5);
    return QIcon(pixmap);
}

}  // namespace

EditSkeletonFactory::EditSkeletonFactory() {
    editSkeleton_ = new QAction(skeletonIcon(), "Edit Skeleton", this);
    editSkeleton_->setCheckable(true);
#if PCSKELETON_MESHLAB_2021_API
    actionList.push_back(editSkeleton_);  // what the base class's actions() lists
#endif
}

pcskeleton::meshlab::EditToolBase* EditSkeletonFactory::makeTool(const QAction* action) const {
    return action == editSkeleton_ ? new pcskeleton::edit::EditSkeletonTool() : nullptr;
}

#if PCSKELETON_MESHLAB_2021_API
QString EditSkeletonFactory::vendor() const { return pcskeleton::meshlab::pluginVendor(); }
QString EditSkeletonFactory::getEditToolDescription(const QAction*) { return description(); }
#else
QString EditSkeletonFactory::getEditToolDescription(QAction*) { return description(); }
#endif

QString EditSkeletonFactory::description() const {
    return pcskeleton::meshlab::withVersion(pcskeleton::edit::EditSkeletonTool::info());
}
