#include "filter_pcskeleton.h"

#include <pcskeleton/laplacian_contraction.h>

#include <vcg/complex/allocate.h>

#include <QFileInfo>

#include <new>

namespace {

const char* const kPaperReference =
    "<br><br>See: <i>Junjie Cao, Andrea Tagliasacchi, Matt Olson, Hao Zhang, Zhixun Su</i><br>"
    "<b>\"Point Cloud Skeletons via Laplacian-Based Contraction\"</b><br>"
    "Shape Modeling International (SMI) 2010, pages 187-197.";

// Contracted layers remember which input vertex each point came from, for thinning.
const char* const kInputIndexAttribute = "pcs_input_index";

struct InputPoints {
    pcskeleton::PointList points;
    std::vector<CMeshO::VertexPointer> vertices;  // the live vertex of each point
};

// Every live vertex is a point; faces, if any, are ignored (polygon soups work).
InputPoints collectPoints(CMeshO& mesh) {
    InputPoints input;
    input.points.reserve(mesh.vn);
    input.vertices.reserve(mesh.vn);
    for (auto& v : mesh.vert) {
        if (v.IsD()) continue;
        input.points.emplace_back(v.P()[0], v.P()[1], v.P()[2]);
        input.vertices.push_back(&v);
    }
    return input;
}

MeshModel* addPointLayer(MeshDocument& md, MeshModel& source, const InputPoints& input,
                         const pcskeleton::PointList& positions, const QString& label) {
    MeshModel* layer = md.addNewMesh("", label, true);
    CMeshO& out = layer->cm;
    auto vertex = vcg::tri::Allocator<CMeshO>::AddVertices(out, positions.size());
    auto inputIndex = vcg::tri::Allocator<CMeshO>::GetPerVertexAttribute<int>(out, kInputIndexAttribute);
    const bool copyColour = source.hasDataMask(MeshModel::MM_VERTCOLOR);
    if (copyColour) layer->updateDataMask(MeshModel::MM_VERTCOLOR);
    for (std::size_t i = 0; i < positions.size(); ++i, ++vertex) {
        vertex->P() = CMeshO::CoordType(positions[i].x(), positions[i].y(), positions[i].z());
        if (copyColour) vertex->C() = input.vertices[i]->C();
        inputIndex[vertex] = static_cast<int>(input.vertices[i] - &source.cm.vert[0]);
    }
    layer->UpdateBoxAndNormals();
    return layer;
}

// MeshLab's layer list cuts a label at its first dot ("bunny.ply contracted" shows as
// "bunny"), hence the source's base name. iteration 0: the final layer, unnumbered.
QString contractedLabel(const MeshModel& source, int iteration) {
    const QString base = QFileInfo(source.label()).completeBaseName();
    return iteration > 0 ? QString("%1 contracted (iteration %2)").arg(base).arg(iteration)
                         : QString("%1 contracted").arg(base);
}

void addContractionParameters(RichParameterList& list) {
    const pcskeleton::ContractionParameters d;
    list.addParam(RichInt("k", d.neighbourCount, "Neighbours (k)",
        "Number of nearest neighbours whose tangent-plane Delaunay triangulation gives each point its 1-ring. "
        "0 = automatic: 1.2% of the points, between 8 and 30 (the paper's rule). Raise it for noisy scans; "
        "lower it if close-by parts (fingers, claws) get connected."));
    list.addParam(RichFloat("contractionWeight", float(d.initialContractionWeight), "Initial contraction weight W_L0",
        "Strength of the Laplacian (shrinking) term in the first iteration, in the normalised frame where the "
        "cloud's longest side is 1.6. 0 = automatic: 1/(5 S0), S0 being the mean 1-ring size. Too high pulls thin "
        "parts into thick ones (paper Fig. 4d); too low lets tips stick out of the shape (Fig. 4a)."));
    list.addParam(RichFloat("attractionWeight", float(d.initialAttractionWeight), "Initial attraction weight W_H0",
        "How strongly points are held at their positions. Acts opposite to W_L0 (paper Fig. 4e-h)."));
    list.addParam(RichFloat("contractionScale", float(d.contractionScale), "Contraction scale s_L",
        "W_L is multiplied by this after every iteration. The paper uses 3; use 2 for shapes with thin parts "
        "between thick ones (paper Fig. 10), at the cost of an extra iteration."));
    // An integer on purpose: MeshLab's dialog shows floats with 3 digits, and would read
    // 2048 back as 2050 on Apply.
    list.addParam(RichInt("maxContractionWeight", int(d.maxContractionWeight), "Maximum W_L",
        "Upper limit of the contraction weight, for numerical stability."));
    list.addParam(RichFloat("maxAttractionWeight", float(d.maxAttractionWeight), "Maximum W_H",
        "Upper limit of a point's attraction weight (it grows as the point's 1-ring shrinks)."));
    list.addParam(RichFloat("laplacianRowLimit", float(d.laplacianRowLimit), "Laplacian row limit",
        "A Laplacian row whose weights add up to more than this is scaled down; guards against the huge "
        "cotangents of nearly flat 1-ring triangles."));
    list.addParam(RichInt("maxIterations", d.maxIterations, "Maximum iterations",
        "Contraction stops after this many iterations at the latest (most models converge in under 5)."));
    list.addParam(RichFloat("terminationThreshold", float(d.terminationThreshold), "Termination threshold",
        "Contraction stops when the total 1-ring size shrank by less than this fraction of its initial value "
        "in the last iteration."));
    list.addParam(RichInt("iterationsToRun", 0, "Iterations to run",
        "Run at most this many iterations, to watch the cloud contract step by step "
        "(0 = until contraction stops)."));
    list.addParam(RichBool("keepEveryIteration", false, "One layer per iteration",
        "Add a layer after every iteration instead of only the final one."));
}

pcskeleton::ContractionParameters readContractionParameters(const RichParameterList& list) {
    pcskeleton::ContractionParameters p;
    p.neighbourCount = list.getInt("k");
    p.initialContractionWeight = list.getFloat("contractionWeight");
    p.initialAttractionWeight = list.getFloat("attractionWeight");
    p.contractionScale = list.getFloat("contractionScale");
    p.maxContractionWeight = list.getInt("maxContractionWeight");
    p.maxAttractionWeight = list.getFloat("maxAttractionWeight");
    p.laplacianRowLimit = list.getFloat("laplacianRowLimit");
    p.maxIterations = list.getInt("maxIterations");
    p.terminationThreshold = list.getFloat("terminationThreshold");
    return p;
}

}  // namespace

FilterPCSkeletonPlugin::FilterPCSkeletonPlugin() {
    typeList << FP_CONTRACT_POINT_CLOUD;
    for (FilterIDType type : typeList) actionList << new QAction(filterName(type), this);
}

QString FilterPCSkeletonPlugin::pluginName() const { return "FilterPCSkeleton"; }

QString FilterPCSkeletonPlugin::filterName(FilterIDType filter) const {
    switch (filter) {
        case FP_CONTRACT_POINT_CLOUD: return "Contract Point Cloud (Laplacian)";
    }
    return {};
}

QString FilterPCSkeletonPlugin::filterInfo(FilterIDType filter) const {
    switch (filter) {
        case FP_CONTRACT_POINT_CLOUD:
            return QString(
                "Contracts the current layer's points towards the shape's curve skeleton by iterated "
                "Laplacian smoothing with cotangent weights on local tangent-plane Delaunay 1-rings. "
                "Adds a new layer with the contracted points (same order as the input's vertices); the input "
                "layer is not changed. Faces are ignored, so meshes, meshes with boundaries and polygon soups "
                "work as point clouds. All parameters are relative to the cloud's size: the defaults are the "
                "paper's.") + kPaperReference;
    }
    return {};
}

MeshFilterInterface::FilterClass FilterPCSkeletonPlugin::getClass(QAction*) { return PointSet; }

int FilterPCSkeletonPlugin::getPreConditions(QAction*) const { return MeshModel::MM_VERTCOORD; }

int FilterPCSkeletonPlugin::postCondition(QAction*) const { return MeshModel::MM_NONE; }

MeshFilterInterface::FILTER_ARITY FilterPCSkeletonPlugin::filterArity(QAction*) const { return SINGLE_MESH; }

void FilterPCSkeletonPlugin::initParameterSet(QAction* action, MeshModel&, RichParameterList& parameters) {
    switch (ID(action)) {
        case FP_CONTRACT_POINT_CLOUD: addContractionParameters(parameters); break;
    }
}

bool FilterPCSkeletonPlugin::applyFilter(QAction* action, MeshDocument& md, const RichParameterList& parameters,
                                         vcg::CallBackPos* cb) {
    try {
        switch (ID(action)) {
            case FP_CONTRACT_POINT_CLOUD: return contractPointCloud(md, parameters, cb);
        }
        errorMessage = "Unknown filter.";
    } catch (const pcskeleton::InvalidInput& e) {
        errorMessage = e.what();
    } catch (const std::bad_alloc&) {
        errorMessage = "Out of memory: try a subsampled cloud (Filters > Sampling > Point Cloud Simplification).";
    } catch (const std::exception& e) {
        errorMessage = QString("Internal error: ") + e.what();
    }
    return false;
}

bool FilterPCSkeletonPlugin::contractPointCloud(MeshDocument& md, const RichParameterList& parameters,
                                                vcg::CallBackPos* cb) {
    MeshModel* source = md.mm();
    if (source == nullptr) {
        errorMessage = "No layer is selected.";
        return false;
    }
    const InputPoints input = collectPoints(source->cm);
    const pcskeleton::ContractionParameters settings = readContractionParameters(parameters);
    const int iterationsToRun = parameters.getInt("iterationsToRun");
    const bool keepEveryIteration = parameters.getBool("keepEveryIteration");
    if (iterationsToRun < 0) {
        errorMessage = "Iterations to run must be 0 (until contraction stops) or positive.";
        return false;
    }

    auto progress = [cb](int percent, const char* what) {
        if (cb) cb(percent, what);
    };
    pcskeleton::ProgressCallback neighbourhoodProgress = [&](int percent, const char* what) {
        progress(percent * 30 / 100, what);
    };
    pcskeleton::LaplacianContraction contraction(input.points, settings, neighbourhoodProgress);
    Log("Contraction of '%s': %zu points, k = %d, W_L0 = %.4g; 1-rings built in %.2f s",
        qUtf8Printable(source->label()), input.points.size(), contraction.neighbourCount(),
        contraction.initialContractionWeight(), contraction.neighbourhoodSeconds());

    const int limit = iterationsToRun > 0 ? std::min(iterationsToRun, settings.maxIterations) : settings.maxIterations;
    int done = 0;
    while (!contraction.finished() && done < limit) {
        const pcskeleton::IterationReport r = contraction.iterate();
        ++done;
        Log("  iteration %d: mean 1-ring size %.4f of initial, W_L = %.4g, %.2f s", r.iteration, r.extentRatio,
            r.contractionWeight, r.seconds);
        progress(30 + 70 * done / limit, "Contracting");
        if (keepEveryIteration && !contraction.finished() && done < limit) {
            addPointLayer(md, *source, input, contraction.contractedPoints(),
                          contractedLabel(*source, r.iteration));
        }
    }

    const QString label = contractedLabel(*source, keepEveryIteration ? done : 0);
    addPointLayer(md, *source, input, contraction.contractedPoints(), label);
    const QString stop = contraction.finished() ? QString::fromStdString(pcskeleton::describe(contraction.stopReason()))
                                                : QString("paused after the requested %1 iteration(s)").arg(done);
    Log("Contraction: %d iteration(s), %s. New layer '%s'.", done, qUtf8Printable(stop), qUtf8Printable(label));
    if (contraction.stopReason() == pcskeleton::StopReason::NumericalFailure) {
        Log(GLLogStream::WARNING, "The last iteration failed numerically; the layer holds the last good positions.");
    }
    return true;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterPCSkeletonPlugin)
