// MeshLab filter plugin exposing pcskeleton (Cao et al., SMI 2010). A thin adapter:
// parameters, layers, progress and log here; every algorithm lives in vcg_ext/.
#pragma once

#include <common/interfaces.h>

#include <pcskeleton/curve_skeleton.h>

#include <functional>

namespace pcskeleton::meshlab {
struct LayerPoints;
}

class FilterPCSkeletonPlugin : public QObject, public MeshFilterInterface {
    Q_OBJECT
    MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
    Q_INTERFACES(MeshFilterInterface)

public:
    enum {
        FP_CONTRACT_POINT_CLOUD,
        FP_COMPUTE_SKELETON,
        FP_SKELETON_FROM_CONTRACTED,
        FP_EXPORT_SKELETON,
        // Skeleton repairs on the selected nodes, in place (MeshLab's convention for edits).
        FP_DELETE_SELECTED_NODES,
        FP_CONNECT_SELECTED_NODES,
        FP_MERGE_SELECTED_NODES,
        FP_SET_RADIUS_OF_SELECTED_NODES,
        FP_RECONSTRUCT_FROM_SKELETON,
    };

    FilterPCSkeletonPlugin();

    QString pluginName() const override;
    QString filterName(FilterIDType filter) const override;
    QString filterInfo(FilterIDType filter) const override;
    FilterClass getClass(QAction* action) override;
    int getPreConditions(QAction* action) const override;
    int postCondition(QAction* action) const override;
    FILTER_ARITY filterArity(QAction* action) const override;
    void initParameterSet(QAction* action, MeshDocument& md, RichParameterList& parameters) override;
    bool applyFilter(QAction* action, MeshDocument& md, const RichParameterList& parameters,
                     vcg::CallBackPos* cb) override;

private:
    bool runFilter(int filter, MeshDocument& md, const RichParameterList& parameters, vcg::CallBackPos* cb);
    // Iterates until the contraction stops or `limit` iterations, logging each one.
    int contract(pcskeleton::LaplacianContraction& contraction, int limit,
                 const std::function<void(int done)>& afterIteration);
    void logContractionStart(const MeshModel& source, const pcskeleton::LaplacianContraction& contraction,
                             std::size_t points);
    void addSkeletonLayers(MeshDocument& md, const MeshModel& source, const pcskeleton::meshlab::LayerPoints& input,
                           const pcskeleton::SkeletonResult& result, bool addSegments);
    // Logs each line of `text`, indented, at `level`.
    void logLines(const QString& text, GLLogStream::Levels level);
    bool contractPointCloud(MeshDocument& md, const RichParameterList& parameters, vcg::CallBackPos* cb);
    bool computeSkeleton(MeshDocument& md, const RichParameterList& parameters, vcg::CallBackPos* cb);
    bool skeletonFromContracted(MeshDocument& md, const RichParameterList& parameters, vcg::CallBackPos* cb);
    bool exportSkeleton(MeshDocument& md, const RichParameterList& parameters);
    bool editSelectedNodes(int filter, MeshDocument& md, const RichParameterList& parameters);
    bool reconstructFromSkeleton(MeshDocument& md, const RichParameterList& parameters, vcg::CallBackPos* cb);
};
