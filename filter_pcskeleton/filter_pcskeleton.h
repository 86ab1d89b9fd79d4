// MeshLab filter plugin exposing pcskeleton (Cao et al., SMI 2010). A thin adapter:
// parameters, layers, progress and log here; every algorithm lives in vcg_ext/.
#pragma once

#include <common/interfaces.h>

class FilterPCSkeletonPlugin : public QObject, public MeshFilterInterface {
    Q_OBJECT
    MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
    Q_INTERFACES(MeshFilterInterface)

public:
    enum { FP_CONTRACT_POINT_CLOUD };

    FilterPCSkeletonPlugin();

    QString pluginName() const override;
    QString filterName(FilterIDType filter) const override;
    QString filterInfo(FilterIDType filter) const override;
    FilterClass getClass(QAction* action) override;
    int getPreConditions(QAction* action) const override;
    int postCondition(QAction* action) const override;
    FILTER_ARITY filterArity(QAction* action) const override;
    void initParameterSet(QAction* action, MeshModel& m, RichParameterList& parameters) override;
    bool applyFilter(QAction* action, MeshDocument& md, const RichParameterList& parameters,
                     vcg::CallBackPos* cb) override;

private:
    bool contractPointCloud(MeshDocument& md, const RichParameterList& parameters, vcg::CallBackPos* cb);
};
