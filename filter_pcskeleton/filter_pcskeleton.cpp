#include "filter_pcskeleton.h"

#include <meshlab_layers/meshlab_terms.h>
#include <meshlab_layers/reconstruction_layer.h>
#include <meshlab_layers/skeleton_layer.h>

#include <pcskeleton/curve_skeleton.h>
#include <pcskeleton/parameter_settings.h>
#include <pcskeleton/editing/skeleton_editing.h>
#include <pcskeleton/io/input_file.h>
#include <pcskeleton/io/branch_io.h>
#include <pcskeleton/io/skeleton_io.h>

#include <vcg/complex/allocate.h>

#include <QDir>
#include <QFileInfo>

#include <new>

using namespace pcskeleton::meshlab;
using pcskeleton::Parameter;

namespace {

const char* const kPaperReference =
    "<br><br>See: <i>Junjie Cao, Andrea Tagliasacchi, Matt Olson, Hao Zhang, Zhixun Su</i><br>"
    "<b>\"Point Cloud Skeletons via Laplacian-Based Contraction\"</b><br>"
    "Shape Modeling International (SMI) 2010, pages 187-197.";

const char* const kEditHelp =
    "<br><br>The skeleton layer is changed in place (the points layer is not). Select nodes with MeshLab's "
    "selection tools or filters, e.g. Filters > Selection > Conditional Vertex Selection with (x > 0), or "
    "Select by Vertex Quality to pick nodes by radius. The same edits, with undo, are in the Edit Skeleton "
    "tool.";

using pcskeleton::ParameterInfo;
using pcskeleton::Stage;
using pcskeleton::ValueType;

// The stages whose parameters each filter's dialog shows.
const std::vector<Stage> kContractionStages = {Stage::Contraction, Stage::PointCleaning};
const std::vector<Stage> kSkeletonStages = {Stage::Contraction, Stage::PointCleaning, Stage::Resolution,
                                            Stage::Thinning};
const std::vector<Stage> kThinningStages = {Stage::PointCleaning, Stage::Thinning};
const std::vector<Stage> kReconstructionStages = {Stage::Reconstruction};

bool inStages(const ParameterInfo& p, const std::vector<Stage>& stages) {
    return std::find(stages.begin(), stages.end(), p.stage) != stages.end();
}

// A dialog field shows a switch the way its label reads ("Detect outliers"), the table's
// value the way its name reads ("keep_outliers").
bool fieldValueOfSwitch(const ParameterInfo& p, double value) { return (value != 0) != p.inverted; }

// The maximum W_L is a whole number in an integer field: MeshLab's float fields show 3
// digits and would read 2048 back as 2050 on Apply.
bool shownAsInteger(const ParameterInfo& p) {
    return p.type == ValueType::Integer || p.id == Parameter::MaxContractionWeight;
}

// One field per parameter of `stages` (the table's label and help), with `advanced` ones
// only or common ones only: the common ones come first, the advanced ones last, behind
// MeshLab's advanced toggle where it has one.
void addParameterField(RichParameterList& list, const ParameterInfo& p, const QString& extraHelp = {}) {
    const double value = pcskeleton::defaultValue(p.id);
    const QString name = p.meshlabName, label = p.label, help = QString(p.help) + extraHelp;
    if (p.type == ValueType::Switch) {
        list.addParam(richParameter<RichBool>(name, fieldValueOfSwitch(p, value), label, help, p.advanced));
    } else if (shownAsInteger(p)) {
        list.addParam(richParameter<RichInt>(name, int(value), label, help, p.advanced));
    } else {
        list.addParam(richParameter<RichFloat>(name, float(value), label, help, p.advanced));
    }
}

void addParameterFields(RichParameterList& list, const std::vector<Stage>& stages, bool advanced) {
    for (const ParameterInfo& p : pcskeleton::parameterTable()) {
        if (inStages(p, stages) && p.advanced == advanced && p.meshlabName) addParameterField(list, p);
    }
}

// The settings a dialog (or an .mlx script) gives: the defaults, or the paper's pipeline
// first, then every field of the table changed from its default.
pcskeleton::Settings settingsOf(const RichParameterList& list, bool paper = false) {
    std::vector<std::pair<Parameter, double>> changed;
    for (const ParameterInfo& p : pcskeleton::parameterTable()) {
        if (!p.meshlabName || !list.hasParameter(p.meshlabName)) continue;
        const double fallback = pcskeleton::defaultValue(p.id);
        double value = 0, shownDefault = 0;
        if (p.type == ValueType::Switch) {
            value = list.getBool(p.meshlabName) != p.inverted ? 1.0 : 0.0;
            shownDefault = fallback;
        } else if (shownAsInteger(p)) {
            value = list.getInt(p.meshlabName);
            shownDefault = double(int(fallback));
        } else {
            value = list.getFloat(p.meshlabName);
            shownDefault = double(float(fallback));
        }
        if (value != shownDefault) changed.emplace_back(p.id, value);
    }
    return pcskeleton::settingsFrom(paper, changed);
}

void addSegmentsLayerField(RichParameterList& list) {
    list.addParam(RichBool("addSegmentsLayer", true, "Add a layer of points coloured by node",
        "Adds a copy of the input points, each coloured by the skeleton node it belongs to (the correspondence), "
        "with the node index in the per-vertex attribute pcs_node. The input layer is not changed."));
}

pcskeleton::ProgressCallback progressOf(vcg::CallBackPos* cb) {
    if (!cb) return {};
    return [cb](int percent, const char* what) { cb(percent, what); };
}

// The layer the contracted layer came from: the one whose label it extends, else any other.
MeshModel* likelySourceOf(MeshDocument& md, MeshModel* contracted) {
    MeshModel* fallback = nullptr;
    for (MeshModel* m : layersOf(md)) {
        if (m == contracted) continue;
        if (contracted && derivedLabel(*m, "contracted") == contracted->label()) return m;
        if (!fallback) fallback = m;
    }
    return fallback ? fallback : contracted;
}

// Mean radius of the selected nodes (of all nodes if none is selected); 0 when the layer
// is not a skeleton.
float defaultRadiusOfSelection(const MeshModel* layer) {
    if (!layer || !notASkeletonReason(*layer).isEmpty()) return 0.0f;
    const pcskeleton::SkeletonGraph skeleton = readSkeletonLayer(*layer);
    std::vector<int> nodes = selectedNodes(*layer);
    if (nodes.empty()) {
        for (std::size_t n = 0; n < skeleton.nodeCount(); ++n) nodes.push_back(int(n));
    }
    double sum = 0.0;
    for (int n : nodes) sum += skeleton.radii[n];
    return nodes.empty() ? 0.0f : float(sum / nodes.size());
}

// "<folder of the points' file>/<layer label>.<extension>" (or _1, _2... if taken): next to
// the data rather than in whatever directory MeshLab was started from.
QString defaultSkeletonFileName(MeshDocument& md, const QString& extension = "ply") {
    MeshModel* layer = md.mm();
    QString name = layer ? QFileInfo(layer->label()).completeBaseName() : QString("skeleton");
    name.replace(' ', '_');
    QString folder;
    if (layer) {
        for (MeshModel* m : {layer, sourceLayerOf(md, *layer)}) {
            if (folder.isEmpty() && m && !m->fullName().isEmpty()) folder = QFileInfo(m->fullName()).absolutePath();
        }
    }
    for (const MeshModel* m : layersOf(md)) {
        if (folder.isEmpty() && !m->fullName().isEmpty()) folder = QFileInfo(m->fullName()).absolutePath();
    }
    // Never propose an existing file, above all the one the skeleton was opened from.
    const QDir directory(folder.isEmpty() ? QDir::homePath() : folder);
    QString fileName = directory.filePath(name + "." + extension);
    for (int copy = 1; QFileInfo::exists(fileName); ++copy) {
        fileName = directory.filePath(QString("%1_%2.%3").arg(name).arg(copy).arg(extension));
    }
    return fileName;
}

// Why `fileName` must not be written, or empty: the file of an open layer never is, an
// existing file only with `overwrite` (the "Replace an existing file" box).
QString refusalToWrite(MeshDocument& md, const QString& fileName, bool overwrite) {
    for (const MeshModel* m : layersOf(md)) {
        if (!m->fullName().isEmpty() && pcskeleton::sameFile(m->fullName().toStdString(), fileName.toStdString())) {
            return QString("Cannot write '%1': it is the file of the open layer '%2', which is never "
                           "overwritten. Choose another name.").arg(fileName, m->label());
        }
    }
    if (QFileInfo::exists(fileName) && !overwrite) {
        return QString("Cannot write '%1': the file exists already. Choose another name, or tick "
                       "'Replace an existing file'.").arg(fileName);
    }
    return {};
}

// The "up" axes of Measure Skeleton Branches, in the order of its list.
const QStringList kUpAxisNames = {"+Z", "+Y", "+X", "-Z", "-Y", "-X"};
const pcskeleton::Point kUpAxes[] = {pcskeleton::Point::UnitZ(),  pcskeleton::Point::UnitY(),
                                     pcskeleton::Point::UnitX(),  -pcskeleton::Point::UnitZ(),
                                     -pcskeleton::Point::UnitY(), -pcskeleton::Point::UnitX()};

}  // namespace

FilterPCSkeletonPlugin::FilterPCSkeletonPlugin() {
    typeList = {FP_CONTRACT_POINT_CLOUD,          FP_COMPUTE_SKELETON,       FP_SKELETON_FROM_CONTRACTED,
                FP_EXPORT_SKELETON,               FP_DELETE_SELECTED_NODES,  FP_CONNECT_SELECTED_NODES,
                FP_MERGE_SELECTED_NODES,          FP_SET_RADIUS_OF_SELECTED_NODES, FP_RECONSTRUCT_FROM_SKELETON,
                FP_MEASURE_BRANCHES};
    for (int type : typeList) actionList.push_back(new QAction(filterName(type), this));
}

QString FilterPCSkeletonPlugin::pluginName() const { return "FilterPCSkeleton"; }

#if PCSKELETON_MESHLAB_2021_API
QString FilterPCSkeletonPlugin::vendor() const { return pluginVendor(); }
#endif

QString FilterPCSkeletonPlugin::filterName(int filter) const {
    switch (filter) {
        case FP_CONTRACT_POINT_CLOUD: return "Contract Point Cloud (Laplacian)";
        case FP_COMPUTE_SKELETON: return "Compute Curve Skeleton (Laplacian Contraction)";
        case FP_SKELETON_FROM_CONTRACTED: return "Skeleton from Contracted Points";
        case FP_EXPORT_SKELETON: return "Export Skeleton (PLY with edges, OBJ, CG)";
        case FP_DELETE_SELECTED_NODES: return "Skeleton: Delete Selected Nodes";
        case FP_CONNECT_SELECTED_NODES: return "Skeleton: Connect the Two Selected Nodes";
        case FP_MERGE_SELECTED_NODES: return "Skeleton: Merge Selected Nodes";
        case FP_SET_RADIUS_OF_SELECTED_NODES: return "Skeleton: Set Radius of Selected Nodes";
        case FP_RECONSTRUCT_FROM_SKELETON: return "Reconstruct Surface from Skeleton";
        case FP_MEASURE_BRANCHES: return "Measure Skeleton Branches";
    }
    return {};
}

QString FilterPCSkeletonPlugin::filterInfo(int filter) const { return withVersion(description(filter)); }

QString FilterPCSkeletonPlugin::description(int filter) const {
    switch (filter) {
        case FP_CONTRACT_POINT_CLOUD:
            return QString(
                "Contracts the current layer's points towards the shape's curve skeleton by iterated "
                "Laplacian smoothing with cotangent weights on local tangent-plane Delaunay 1-rings. "
                "Adds a new layer with the contracted points (same order as the input's vertices); the input "
                "layer is not changed. Faces are ignored, so meshes, meshes with boundaries and polygon soups "
                "work as point clouds. All parameters are relative to the cloud's size. The defaults are the "
                "paper's, plus two steps it does not have: outliers are set aside and a noisy cloud is contracted "
                "through a denoised copy (untick 'Detect outliers' and set 'Denoising passes' to 0 for the paper's "
                "contraction exactly; on a cloud of fewer than 1667 points, also set k to 1.2% of its points, at "
                "least 8: the automatic k may be more than the paper's there).") + kPaperReference;
        case FP_COMPUTE_SKELETON:
            // Short: with every field of MeshLab 2020.09's dialog it must fit a 1024-pixel screen.
            return QString(
                "Computes the curve skeleton of the current layer's points by Laplacian contraction and "
                "thinning. Adds a skeleton layer (radius in vertex quality) and logs a quality report; the input "
                "is not changed. Save it with Export Skeleton (MeshLab's PLY export drops edges).") +
                kPaperReference;
        case FP_SKELETON_FROM_CONTRACTED:
            return QString(
                "Thinning alone: turns the current layer, made by Contract Point Cloud (Laplacian), into a "
                "curve skeleton layer. The source layer gives the original points, from which the 1-rings and "
                "the node positions and radii are taken. Lets you contract step by step, look, then thin.") +
                kPaperReference;
        case FP_EXPORT_SKELETON:
            return QString(
                "Writes the current skeleton layer with its edges, which MeshLab's own exporters drop or "
                "cannot express. The format follows the file extension: .ply (vertices with radius and "
                "quality, element edge; MeshLab opens it again with its edges), .obj (v and l lines) or .cg "
                "(the Starlab curve-skeleton format used by skeleton benchmarks; no radius).");
        case FP_DELETE_SELECTED_NODES:
            return QString("Deletes the selected nodes of the current skeleton layer and their bones, e.g. to cut a "
                           "wrong loop or remove a spur. Their points then belong to no node.") + kEditHelp;
        case FP_CONNECT_SELECTED_NODES:
            return QString("Adds a bone between the two selected nodes of the current skeleton layer, e.g. to "
                           "restore a loop or a limb the scan missed. Exactly two nodes must be selected.") +
                   kEditHelp;
        case FP_MERGE_SELECTED_NODES:
            return QString("Replaces the selected nodes of the current skeleton layer by one node at their "
                           "centroid, with their mean radius, all their bones to other nodes and all their points; "
                           "bones between them disappear (a small spurious loop closes up). The merged node stays "
                           "selected.") + kEditHelp;
        case FP_SET_RADIUS_OF_SELECTED_NODES:
            return QString("Sets the radius of the selected nodes of the current skeleton layer (the thickness "
                           "reconstruction gives the shape there). The radius is also the vertex quality.") +
                   kEditHelp;
        case FP_RECONSTRUCT_FROM_SKELETON:
            return QString(
                "Rebuilds a closed surface from a point cloud and its curve skeleton (Section V of the paper), for "
                "scans with missing data: where the scan has points the surface passes through them, where it "
                "has none the skeleton decides. A loop in the skeleton gives a handle in the surface, a loop cut in "
                "the skeleton gives none, so fixing the skeleton (Edit Skeleton, or the Skeleton: filters) fixes "
                "the surface's topology. Solves for a smooth scalar field on a grid: 0 at the points, minus the "
                "node radius along the bones, positive beyond K radii from the skeleton; the surface is its zero "
                "level set (marching cubes). Adds a mesh layer; the log gives the grid, the solver's effort and "
                "the genus of the result. Neither input layer is changed.") +
                kPaperReference;
        case FP_MEASURE_BRANCHES:
            return QString(
                "Splits the current skeleton layer into branches (chains of bones between tips and junctions, or "
                "whole loops) grown from each part's root, its lowest node along the up axis, and logs for each its "
                "order (1 for the main axis from the root, 2 for what grows from it, ...; the main axis goes on "
                "into the longest continuation), length, radii, volume, angle to its parent and number of points. "
                "Adds a copy of the skeleton's points coloured by branch, with the branch in the per-vertex "
                "attribute pcs_branch, and writes the table as CSV or JSON if a file is given. Neither layer is "
                "changed.");
    }
    return {};
}

FilterPCSkeletonPlugin::FilterClass FilterPCSkeletonPlugin::filterClass(int filter) const {
    // Also listed with MeshLab's other surface reconstructions.
    return filter == FP_RECONSTRUCT_FROM_SKELETON ? FilterClass(PointSet | Remeshing) : PointSet;
}

int FilterPCSkeletonPlugin::changesOf(int filter) const {
    switch (filter) {
        case FP_DELETE_SELECTED_NODES:
        case FP_CONNECT_SELECTED_NODES:
        case FP_MERGE_SELECTED_NODES:
        case FP_SET_RADIUS_OF_SELECTED_NODES:
            return MeshModel::MM_GEOMETRY_AND_TOPOLOGY_CHANGE | MeshModel::MM_VERTQUALITY |
                   MeshModel::MM_VERTFLAGSELECT;
    }
    return MeshModel::MM_NONE;  // the other filters add layers and change none
}

bool FilterPCSkeletonPlugin::takesTwoLayers(int filter) const {
    return filter == FP_SKELETON_FROM_CONTRACTED || filter == FP_RECONSTRUCT_FROM_SKELETON;
}

#if PCSKELETON_MESHLAB_2021_API
RichParameterList FilterPCSkeletonPlugin::initParameterList(const QAction* action, const MeshDocument& md) {
    RichParameterList parameters;
    // The defaults only read the document; MeshLab's layer parameter keeps a pointer to it.
    addParameters(ID(action), const_cast<MeshDocument&>(md), parameters);
    return parameters;
}

std::map<std::string, QVariant> FilterPCSkeletonPlugin::applyFilter(const QAction* action,
                                                                    const RichParameterList& parameters,
                                                                    MeshDocument& md, unsigned int&,
                                                                    vcg::CallBackPos* cb) {
    if (!apply(ID(action), md, parameters, cb)) throw MLException(failure_);
    return {};
}
#else
bool FilterPCSkeletonPlugin::applyFilter(QAction* action, MeshDocument& md, const RichParameterList& parameters,
                                         vcg::CallBackPos* cb) {
    const bool done = apply(ID(action), md, parameters, cb);
    if (!done) errorMessage = failure_;
    return done;
}
#endif

void FilterPCSkeletonPlugin::addParameters(int filter, MeshDocument& md, RichParameterList& parameters) {
    switch (filter) {
        case FP_CONTRACT_POINT_CLOUD:
            addParameterFields(parameters, kContractionStages, false);
            parameters.addParam(RichInt("iterationsToRun", 0, "Iterations to run (0 = all)",
                "Run at most this many iterations, to watch the cloud contract step by step "
                "(0 = until contraction stops)."));
            parameters.addParam(RichBool("keepEveryIteration", false, "One layer per iteration",
                "Add a layer after every iteration instead of only the final one."));
            addParameterFields(parameters, kContractionStages, true);
            break;
        case FP_COMPUTE_SKELETON:
            addParameterFields(parameters, kSkeletonStages, false);
            addSegmentsLayerField(parameters);
            parameters.addParam(RichBool("addContractedLayer", false, "Add the contracted points layer",
                "Also adds the contracted points as a layer, e.g. to thin them again later with other settings "
                "(Skeleton from Contracted Points)."));
            parameters.addParam(RichBool("paperPipeline", false, "The paper's pipeline, then my changes",
                "The paper's steps only: no outlier detection, denoising, facing walls kept apart, sheets' medial "
                "axes, re-centring, refinement, tip extension, gap bridging, stretched-link limit or subsample; "
                "then every field changed from its default "
                "applies on top (tick Refine too for the paper plus refinement). For comparison with the paper "
                "and other implementations of it."));
            addParameterFields(parameters, kSkeletonStages, true);
            break;
        case FP_SKELETON_FROM_CONTRACTED:
            parameters.addParam(layerParameter("sourceLayer", likelySourceOf(md, md.mm()), md, "Original points",
                "The layer that was contracted: its points give the 1-rings, the node positions and the radii."));
            addParameterField(parameters, pcskeleton::parameterInfo(Parameter::NeighbourCount),
                " Use the value the contraction used.");
            addParameterFields(parameters, kThinningStages, false);
            addSegmentsLayerField(parameters);
            addParameterFields(parameters, kThinningStages, true);
            break;
        case FP_EXPORT_SKELETON: {
            parameters.addParam(FileSaveParameter("fileName", defaultSkeletonFileName(md),
                "Skeleton (*.ply *.obj *.cg)", "File",
                "Where to write the skeleton; .ply, .obj or .cg. Empty, or only an extension such as .obj (for "
                "scripts): next to the points' file, named after the layer (e.g. elephant_skeleton.ply), never "
                "an existing file. The file of an open layer is never written."));
            parameters.addParam(RichBool("overwrite", false, "Replace an existing file",
                "Write over a file that exists already (never over the file of an open layer). Off: an existing "
                "file is refused and left as it is."));
            break;
        }
        case FP_SET_RADIUS_OF_SELECTED_NODES:
            parameters.addParam(RichFloat("radius", defaultRadiusOfSelection(md.mm()), "Radius",
                "The new radius of every selected node, in the cloud's units (default: the mean radius of the "
                "selected nodes). Larger makes the reconstructed surface thicker there."));
            break;
        case FP_RECONSTRUCT_FROM_SKELETON: {
            parameters.addParam(layerParameter("pointsLayer", defaultPointsLayer(md), md, "Points",
                "The scan: the surface passes through its points. Faces, if any, are ignored."));
            parameters.addParam(layerParameter("skeletonLayer", defaultSkeletonLayer(md), md, "Skeleton",
                "The curve skeleton of these points, edited or not: its bones and node radii say where the inside "
                "is, and its loops become the surface's handles."));
            addParameterFields(parameters, kReconstructionStages, false);
            addParameterFields(parameters, kReconstructionStages, true);
            break;
        }
        case FP_MEASURE_BRANCHES:
            parameters.addParam(RichEnum("upAxis", 0, kUpAxisNames, "Up axis",
                "Each part of the skeleton grows from its lowest node along this axis (the base of a plant or a "
                "tree), unless a root node is given."));
            parameters.addParam(RichInt("rootNode", -1, "Root node",
                "The node its part grows from, numbered as the skeleton layer's vertices (-1: the lowest node "
                "along the up axis)."));
            parameters.addParam(FileSaveParameter("tableFile", "", "Branch table (*.csv *.json)", "Table file",
                "Also write the table to this file, .csv or .json (empty: only the log). The file of an open "
                "layer is never written."));
            parameters.addParam(RichBool("overwrite", false, "Replace an existing file",
                "Write over a table file that exists already. Off: an existing file is refused and left as it is."));
            break;
    }
}

bool FilterPCSkeletonPlugin::apply(int filter, MeshDocument& md, const RichParameterList& parameters,
                                   vcg::CallBackPos* cb) {
    failure_.clear();
    bool done = false;
    try {
        done = runFilter(filter, md, parameters, cb);
    } catch (const pcskeleton::InvalidInput& e) {
        failure_ = describeForMeshLab(e.problem());
    } catch (const std::bad_alloc&) {
        failure_ = "Out of memory: try a subsampled cloud (Filters > Sampling > Point Cloud Simplification).";
    } catch (const std::exception& e) {
        failure_ = QString("Internal error: ") + e.what();
    }
    // meshlabserver prints the log but not the error message: without this, a failing
    // script would only say "Problem with filter".
    if (!done) writeLog(*this, GLLogStream::WARNING, "%s", qUtf8Printable(failure_));
    return done;
}

bool FilterPCSkeletonPlugin::runFilter(int filter, MeshDocument& md, const RichParameterList& parameters,
                                       vcg::CallBackPos* cb) {
    if (md.mm() == nullptr) {
        failure_ = "No layer is selected.";
        return false;
    }
    switch (filter) {
        case FP_CONTRACT_POINT_CLOUD: return contractPointCloud(md, parameters, cb);
        case FP_COMPUTE_SKELETON: return computeSkeleton(md, parameters, cb);
        case FP_SKELETON_FROM_CONTRACTED: return skeletonFromContracted(md, parameters, cb);
        case FP_EXPORT_SKELETON: return exportSkeleton(md, parameters);
        case FP_DELETE_SELECTED_NODES:
        case FP_CONNECT_SELECTED_NODES:
        case FP_MERGE_SELECTED_NODES:
        case FP_SET_RADIUS_OF_SELECTED_NODES: return editSelectedNodes(filter, md, parameters);
        case FP_RECONSTRUCT_FROM_SKELETON: return reconstructFromSkeleton(md, parameters, cb);
        case FP_MEASURE_BRANCHES: return measureBranches(md, parameters);
    }
    failure_ = "Unknown filter.";
    return false;
}

int FilterPCSkeletonPlugin::contract(pcskeleton::LaplacianContraction& contraction, int limit,
                                     const std::function<void(int done)>& afterIteration) {
    int done = 0;
    while (!contraction.finished() && done < limit) {
        const pcskeleton::IterationReport r = contraction.iterate();
        ++done;
        writeLog(*this, "  iteration %d: mean 1-ring size %.4f of initial, W_L = %.4g, %.2f s", r.iteration, r.extentRatio,
            r.contractionWeight, r.seconds);
        afterIteration(done);
    }
    if (contraction.stopReason() == pcskeleton::StopReason::NumericalFailure) {
        writeLog(*this, GLLogStream::WARNING, "The last iteration failed numerically; the result uses the last good positions.");
    }
    return done;
}

void FilterPCSkeletonPlugin::logContractionStart(const MeshModel& source,
                                                 const pcskeleton::LaplacianContraction& contraction,
                                                 std::size_t points) {
    writeLog(*this, "Contraction of '%s': %zu points, k = %d, W_L0 = %.4g; 1-rings built in %.2f s",
        qUtf8Printable(source.label()), points, contraction.neighbourCount(), contraction.initialContractionWeight(),
        contraction.neighbourhoodSeconds());
}

bool FilterPCSkeletonPlugin::contractPointCloud(MeshDocument& md, const RichParameterList& parameters,
                                                vcg::CallBackPos* cb) {
    MeshModel& source = *md.mm();
    const LayerPoints input = collectPoints(source);
    // Every point is contracted: the new layer has one point per vertex of the input.
    pcskeleton::SkeletonParameters pipelineParameters = settingsOf(parameters).skeleton;
    pipelineParameters.resolution.maxContractedPoints = 0;
    const pcskeleton::ContractionParameters& settings = pipelineParameters.contraction;
    const int iterationsToRun = parameters.getInt("iterationsToRun");
    const bool keepEveryIteration = parameters.getBool("keepEveryIteration");
    if (iterationsToRun < 0) {
        failure_ = "Iterations to run must be 0 (until contraction stops) or positive.";
        return false;
    }
    const pcskeleton::ProgressCallback progress = progressOf(cb);
    pcskeleton::SkeletonPipeline pipeline(input.points, pipelineParameters, pcskeleton::progressRange(progress, 0, 30));
    pcskeleton::LaplacianContraction& contraction = pipeline.contraction();
    logContractionStart(source, contraction, input.points.size());

    const int limit = iterationsToRun > 0 ? std::min(iterationsToRun, settings.maxIterations) : settings.maxIterations;
    const int done = contract(contraction, limit, [&](int iteration) {
        pcskeleton::report(progress, 30 + 70 * iteration / limit, "Contracting");
        if (keepEveryIteration && !contraction.finished() && iteration < limit) {
            addPointLayer(md, source, input, contraction.contractedPoints(),
                          derivedLabel(source, QString("contracted (iteration %1)").arg(iteration)));
        }
    });

    const QString label =
        derivedLabel(source, keepEveryIteration ? QString("contracted (iteration %1)").arg(done) : "contracted");
    addPointLayer(md, source, input, contraction.contractedPoints(), label);
    const QString stop = contraction.finished() ? QString::fromStdString(pcskeleton::describe(contraction.stopReason()))
                                                : QString("paused after the requested %1 iteration(s)").arg(done);
    writeLog(*this, "Contraction: %d iteration(s), %s. New layer '%s'.", done, qUtf8Printable(stop), qUtf8Printable(label));
    return true;
}

void FilterPCSkeletonPlugin::addSkeletonLayers(MeshDocument& md, const MeshModel& source, const LayerPoints& input,
                                               const pcskeleton::SkeletonResult& result, bool addSegments) {
    if (addSegments) addSegmentsLayer(md, input, result.skeleton, derivedLabel(source, "segments"));
    const QString label = derivedLabel(source, "skeleton");
    addSkeletonLayer(md, source, input, result.skeleton, label);
    writeLog(*this, "Skeleton '%s', quality report:", qUtf8Printable(label));
    logLines(QString::fromStdString(pcskeleton::describeFindings(result.quality)), GLLogStream::FILTER);
    const std::vector<pcskeleton::QualityWarning> warnings = result.quality.warnings();
    if (warnings.empty()) logLines("No warnings.", GLLogStream::FILTER);
    for (const pcskeleton::QualityWarning& w : warnings)
        logLines("Warning: " + describeForMeshLab(w.problem), GLLogStream::WARNING);
    const pcskeleton::StageSeconds& seconds = result.seconds;
    writeLog(*this, "Time: subsampling %.2f s, 1-rings %.2f s, contraction %.2f s, thinning %.2f s, embedding %.2f s, "
        "finishing %.2f s.", seconds.subsampling, seconds.neighbourhoods, seconds.contraction, seconds.thinning, seconds.embedding, seconds.finishing);
}

bool FilterPCSkeletonPlugin::computeSkeleton(MeshDocument& md, const RichParameterList& parameters,
                                             vcg::CallBackPos* cb) {
    MeshModel& source = *md.mm();
    const LayerPoints input = collectPoints(source);
    const pcskeleton::SkeletonParameters pipelineParameters =
        settingsOf(parameters, parameters.getBool("paperPipeline")).skeleton;
    const pcskeleton::ContractionParameters& settings = pipelineParameters.contraction;
    const pcskeleton::ProgressCallback progress = progressOf(cb);
    pcskeleton::SkeletonPipeline pipeline(input.points, pipelineParameters, pcskeleton::progressRange(progress, 0, 25));
    const pcskeleton::ContractionInput& work = pipeline.input();
    if (work.subsampled()) {
        writeLog(*this, "Multi-resolution: %zu of the %zu points contracted (one per cube of side %.4g); every point gets the node "
            "of its cube's point.", work.points().size(), input.points.size(), work.subsample().cellSize);
    }
    pcskeleton::LaplacianContraction& contraction = pipeline.contraction();
    logContractionStart(source, contraction, work.points().size());
    const int done = contract(contraction, settings.maxIterations, [&](int iteration) {
        pcskeleton::report(progress, 25 + 65 * iteration / settings.maxIterations, "Contracting");
    });
    writeLog(*this, "Contraction: %d iteration(s), %s.", done, pcskeleton::describe(contraction.stopReason()).c_str());

    pcskeleton::SkeletonResult result = pipeline.skeleton(pcskeleton::progressRange(progress, 90, 100));
    if (parameters.getBool("addContractedLayer")) {
        addPointLayer(md, source, input, result.contraction.contracted, derivedLabel(source, "contracted"));
    }
    addSkeletonLayers(md, source, input, result, parameters.getBool("addSegmentsLayer"));
    return true;
}

bool FilterPCSkeletonPlugin::skeletonFromContracted(MeshDocument& md, const RichParameterList& parameters,
                                                    vcg::CallBackPos* cb) {
    MeshModel* source = layerParameterValue(md, parameters, "sourceLayer");
    LayerPoints input;
    const pcskeleton::PointList contracted = readContractedLayer(*md.mm(), source, input);
    const pcskeleton::Settings thinning = settingsOf(parameters);
    const pcskeleton::SkeletonResult result = pcskeleton::skeletonFromContractedPoints(
        input.points, contracted, thinning.skeleton.contraction, thinning.skeleton.graph, progressOf(cb));
    addSkeletonLayers(md, *source, input, result, parameters.getBool("addSegmentsLayer"));
    return true;
}

bool FilterPCSkeletonPlugin::exportSkeleton(MeshDocument& md, const RichParameterList& parameters) {
    const MeshModel& layer = *md.mm();
    const QString reason = notASkeletonReason(layer);
    if (!reason.isEmpty()) {
        failure_ = reason;
        return false;
    }
    QString fileName = parameters.getSaveFileName("fileName");
    if (fileName.isEmpty() || (fileName.startsWith('.') && !fileName.contains('/'))) {
        fileName = defaultSkeletonFileName(md, fileName.isEmpty() ? QString("ply") : fileName.mid(1).toLower());
    }
    if (!pcskeleton::isSkeletonFileName(fileName.toStdString())) {
        failure_ = QString("Cannot write '%1': the file name must end in .ply, .obj or .cg.").arg(fileName);
        return false;
    }
    failure_ = refusalToWrite(md, fileName, parameters.getBool("overwrite"));
    if (!failure_.isEmpty()) return false;
    const pcskeleton::SkeletonGraph skeleton = readSkeletonLayer(layer);
    pcskeleton::writeSkeleton(skeleton, fileName.toStdString());
    writeLog(*this, "Skeleton '%s' written to '%s': %s.", qUtf8Printable(layer.label()),
        qUtf8Printable(QFileInfo(fileName).absoluteFilePath()),
        pcskeleton::describe(pcskeleton::analyseTopology(skeleton)).c_str());
    return true;
}

bool FilterPCSkeletonPlugin::measureBranches(MeshDocument& md, const RichParameterList& parameters) {
    const MeshModel& layer = *md.mm();
    failure_ = notASkeletonReason(layer);
    if (!failure_.isEmpty()) return false;
    const pcskeleton::SkeletonGraph skeleton = readSkeletonLayer(layer);
    pcskeleton::BranchOptions options;
    const int axis = parameters.getEnum("upAxis");
    if (axis < 0 || axis >= kUpAxisNames.size()) {
        failure_ = "Unknown up axis.";
        return false;
    }
    options.up = kUpAxes[axis];
    options.root = parameters.getInt("rootNode");
    // With the layer the skeleton was computed from, each point of a junction goes to the
    // branch it lies along (the correspondence is by that layer's vertex index).
    MeshModel* source = sourceLayerOf(md, layer);
    const LayerPoints input = source != nullptr ? collectPoints(*source) : LayerPoints{};
    pcskeleton::PointList pointOfSlot(skeleton.pointNode.size(), pcskeleton::Point::Zero());
    std::size_t placed = 0;
    for (std::size_t i = 0; i < input.points.size(); ++i) {
        const std::size_t slot = std::size_t(input.vertexIndex[i]);
        if (slot < pointOfSlot.size()) pointOfSlot[slot] = input.points[i], ++placed;
    }
    const pcskeleton::SkeletonBranches branches = placed > 0 ? pcskeleton::measureBranches(skeleton, pointOfSlot, options)
                                                              : pcskeleton::measureBranches(skeleton, options);
    const QString fileName = parameters.getSaveFileName("tableFile");
    if (!fileName.isEmpty()) {
        if (!pcskeleton::isBranchTableFileName(fileName.toStdString())) {
            failure_ = QString("Cannot write '%1': the table file's name must end in .csv or .json.").arg(fileName);
            return false;
        }
        failure_ = refusalToWrite(md, fileName, parameters.getBool("overwrite"));
        if (!failure_.isEmpty()) return false;
        pcskeleton::writeBranchTable(branches, fileName.toStdString());
    }
    writeLog(*this, "Branches of '%s' (up axis %s): %s.", qUtf8Printable(layer.label()),
             qUtf8Printable(kUpAxisNames[axis]), pcskeleton::describe(branches).c_str());
    for (std::size_t b = 0; b < branches.branches.size(); ++b) {
        const pcskeleton::Branch& branch = branches.branches[b];
        const QString angle = branch.parent < 0 ? QString("from the root")
                                                : QString("%1 degrees from branch %2")
                                                      .arg(branch.angleToParent, 0, 'f', 1)
                                                      .arg(branch.parent);
        writeLog(*this, "  branch %zu: order %d, %s, length %g, radius %g at the base and %g at the tip, volume %g, "
                 "%d points%s", b, branch.order, qUtf8Printable(angle), branch.length, branch.baseRadius,
                 branch.tipRadius, branch.volume, branch.points, branch.closesLoop ? ", closes a loop" : "");
    }
    if (!fileName.isEmpty()) {
        writeLog(*this, "Branch table written to '%s'.", qUtf8Printable(QFileInfo(fileName).absoluteFilePath()));
    }
    if (source == nullptr || skeleton.pointNode.empty()) {
        writeLog(*this, "No points coloured by branch: the layer the skeleton was computed from is not open.");
        return true;
    }
    std::vector<int> labels(input.points.size(), -1);
    for (std::size_t i = 0; i < input.points.size(); ++i) {
        const std::size_t slot = std::size_t(input.vertexIndex[i]);
        if (slot < branches.pointBranch.size()) labels[i] = branches.pointBranch[slot];
    }
    addLabelledPointLayer(md, input, labels, int(branches.branches.size()), kBranchAttribute,
                          derivedLabel(*source, "branches"));
    return true;
}

bool FilterPCSkeletonPlugin::editSelectedNodes(int filter, MeshDocument& md, const RichParameterList& parameters) {
    MeshModel& layer = *md.mm();
    const QString reason = notASkeletonReason(layer);
    if (!reason.isEmpty()) {
        failure_ = reason;
        return false;
    }
    pcskeleton::SkeletonGraph skeleton = readSkeletonLayer(layer);
    const int filledRadii = pcskeleton::fillMissingRadii(skeleton);
    const std::vector<int> selected = selectedNodes(layer);
    if (selected.empty()) {
        failure_ = QString("No node of '%1' is selected. Select nodes first (e.g. Filters > Selection > "
                               "Conditional Vertex Selection), or use the Edit Skeleton tool.").arg(layer.label());
        return false;
    }
    pcskeleton::SkeletonEditor editor(std::move(skeleton));
    std::vector<int> selectedAfter = selected;
    switch (filter) {
        case FP_DELETE_SELECTED_NODES:
            editor.deleteNodes(selected);
            selectedAfter.clear();
            break;
        case FP_CONNECT_SELECTED_NODES: {
            const auto [a, b] = pcskeleton::exactlyTwoNodes(selected, "connect nodes");
            editor.connect(a, b);
            break;
        }
        case FP_MERGE_SELECTED_NODES: selectedAfter = {editor.mergeNodes(selected)}; break;
        case FP_SET_RADIUS_OF_SELECTED_NODES: editor.setRadius(selected, parameters.getFloat("radius")); break;
    }
    writeSkeletonLayer(layer, editor.skeleton());
    selectNodes(layer, selectedAfter);
    if (filledRadii > 0) {
        writeLog(*this, GLLogStream::WARNING, "%d node(s) of '%s' had no radius; they took their neighbours' radius.", filledRadii,
            qUtf8Printable(layer.label()));
    }
    writeLog(*this, "Skeleton '%s': %s; now %s.", qUtf8Printable(layer.label()), editor.undoText().c_str(),
        pcskeleton::describe(pcskeleton::analyseTopology(editor.graph())).c_str());
    return true;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterPCSkeletonPlugin)

bool FilterPCSkeletonPlugin::reconstructFromSkeleton(MeshDocument& md, const RichParameterList& parameters,
                                                     vcg::CallBackPos* cb) {
    MeshModel* points = layerParameterValue(md, parameters, "pointsLayer");
    MeshModel* skeleton = layerParameterValue(md, parameters, "skeletonLayer");
    if (!points || !skeleton) {
        failure_ = "Choose a point layer and a skeleton layer.";
        return false;
    }
    const ReconstructedLayer result =
        addReconstructionLayer(md, *points, *skeleton, settingsOf(parameters).reconstruction,
                               progressOf(cb));
    writeLog(*this, "Reconstruction '%s' from '%s' and '%s':", qUtf8Printable(result.layer->label()),
        qUtf8Printable(points->label()), qUtf8Printable(skeleton->label()));
    logLines(QString::fromStdString(pcskeleton::describeFindings(result.report)), GLLogStream::FILTER);
    for (const pcskeleton::ReconstructionWarning& w : result.report.warnings)
        logLines("warning: " + describeForMeshLab(w.problem), GLLogStream::WARNING);
    return true;
}

void FilterPCSkeletonPlugin::logLines(const QString& text, GLLogStream::Levels level) {
    for (const QString& line : text.split('\n')) writeLog(*this, level, "  %s", qUtf8Printable(line));
}
