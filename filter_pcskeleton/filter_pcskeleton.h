// MeshLab filter plugin exposing pcskeleton (Cao et al., SMI 2010). A thin adapter:
// parameters, layers, progress and log here; every algorithm lives in vcg_ext/.
#pragma once

#include <meshlab_layers/meshlab_compat.h>

#include <pcskeleton/curve_skeleton.h>

#include <functional>

namespace pcskeleton::meshlab {
struct LayerPoints;
}

class FilterPCSkeletonPlugin : public QObject, public pcskeleton::meshlab::FilterPluginBase {
    Q_OBJECT
#if PCSKELETON_MESHLAB_2021_API
    MESHLAB_PLUGIN_IID_EXPORTER(FILTER_PLUGIN_IID)
    Q_INTERFACES(FilterPlugin)
#else
    MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
    Q_INTERFACES(MeshFilterInterface)
#endif

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
        FP_MEASURE_BRANCHES,
    };

    FilterPCSkeletonPlugin();

    QString pluginName() const override;
    QString filterName(int filter) const override;
    QString filterInfo(int filter) const override;
#if PCSKELETON_MESHLAB_2021_API
    QString vendor() const override;
#endif

    // MeshLab's entry points, whose signatures changed in 2021.05: each forwards to the
    // version-neutral member of the same purpose.
#if PCSKELETON_MESHLAB_2021_API
    FilterClass getClass(const QAction* action) const override { return filterClass(ID(action)); }
    int getPreConditions(const QAction*) const override { return MeshModel::MM_VERTCOORD; }
    int postCondition(const QAction* action) const override { return changesOf(ID(action)); }
    FilterArity filterArity(const QAction* action) const override {
        return takesTwoLayers(ID(action)) ? FIXED : SINGLE_MESH;
    }
    RichParameterList initParameterList(const QAction* action, const MeshDocument& md) override;
    std::map<std::string, QVariant> applyFilter(const QAction* action, const RichParameterList& parameters,
                                                MeshDocument& md, unsigned int& postConditionMask,
                                                vcg::CallBackPos* cb) override;
#else
    FilterClass getClass(QAction* action) override { return filterClass(ID(action)); }
    int getPreConditions(QAction*) const override { return MeshModel::MM_VERTCOORD; }
    int postCondition(QAction* action) const override { return changesOf(ID(action)); }
    FILTER_ARITY filterArity(QAction* action) const override { return takesTwoLayers(ID(action)) ? FIXED : SINGLE_MESH; }
    void initParameterSet(QAction* action, MeshDocument& md, RichParameterList& parameters) override {
        addParameters(ID(action), md, parameters);
    }
    bool applyFilter(QAction* action, MeshDocument& md, const RichParameterList& parameters,
                     vcg::CallBackPos* cb) override;
#endif

private:
    QString description(int filter) const;  // filterInfo without the version line
    FilterClass filterClass(int filter) const;
    int changesOf(int filter) const;  // MeshLab's post-condition mask
    bool takesTwoLayers(int filter) const;
    void addParameters(int filter, MeshDocument& md, RichParameterList& parameters);
    // Runs the filter; on failure logs the reason, keeps it in failure_ and returns false.
    bool apply(int filter, MeshDocument& md, const RichParameterList& parameters, vcg::CallBackPos* cb);
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
    bool measureBranches(MeshDocument& md, const RichParameterList& parameters);

    QString failure_;  // why the last filter failed, for MeshLab's error message
};
