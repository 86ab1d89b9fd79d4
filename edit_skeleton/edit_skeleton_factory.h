// The Edit Skeleton entry on MeshLab's Edit menu and toolbar: the plugin object MeshLab
// loads, which makes an EditSkeletonTool each time the user starts the tool.
#pragma once

#include <meshlab_layers/meshlab_compat.h>

// In the global namespace, as MeshLab's plugin macro names ::meshlab unqualified (and
// pcskeleton::meshlab would hide it).
class EditSkeletonFactory : public QObject, public pcskeleton::meshlab::EditPluginBase {
    Q_OBJECT
#if PCSKELETON_MESHLAB_2021_API
    MESHLAB_PLUGIN_IID_EXPORTER(EDIT_PLUGIN_IID)
    Q_INTERFACES(EditPlugin)
#else
    MESHLAB_PLUGIN_IID_EXPORTER(MESH_EDIT_INTERFACE_FACTORY_IID)
    Q_INTERFACES(MeshEditInterfaceFactory)
#endif

public:
    EditSkeletonFactory();

    // MeshLab's entry points, renamed in 2021.05.
#if PCSKELETON_MESHLAB_2021_API
    QString pluginName() const override { return "EditSkeleton"; }
    QString vendor() const override;
    EditTool* getEditTool(const QAction* action) override { return makeTool(action); }
    QString getEditToolDescription(const QAction*) override;
#else
    QList<QAction*> actions() const override { return {editSkeleton_}; }
    MeshEditInterface* getMeshEditInterface(QAction* action) override { return makeTool(action); }
    QString getEditToolDescription(QAction*) override;
#endif

private:
    QString description() const;  // the tool's description with the version
    pcskeleton::meshlab::EditToolBase* makeTool(const QAction* action) const;

    QAction* editSkeleton_;
};
