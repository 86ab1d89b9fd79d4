// The Edit Skeleton entry on MeshLab's Edit menu and toolbar: the plugin object MeshLab
// loads, which makes an EditSkeletonTool each time the user starts the tool.
#pragma once

#include <common/interfaces.h>

namespace pcskeleton::edit {

class EditSkeletonFactory : public QObject, public MeshEditInterfaceFactory {
    Q_OBJECT
    MESHLAB_PLUGIN_IID_EXPORTER(MESH_EDIT_INTERFACE_FACTORY_IID)
    Q_INTERFACES(MeshEditInterfaceFactory)

public:
    EditSkeletonFactory();
    QList<QAction*> actions() const override { return {editSkeleton_}; }
    MeshEditInterface* getMeshEditInterface(QAction* action) override;
    QString getEditToolDescription(QAction* action) override;

private:
    QAction* editSkeleton_;
};

}  // namespace pcskeleton::edit
