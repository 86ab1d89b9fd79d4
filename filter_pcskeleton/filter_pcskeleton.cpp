#include "filter_pcskeleton.h"

#include <meshlab_layers/meshlab_terms.h>
#include <meshlab_layers/reconstruction_layer.h>
#include <meshlab_layers/skeleton_layer.h>

#include <pcskeleton/curve_skeleton.h>
#include <pcskeleton/editing/skeleton_editing.h>
#include <pcskeleton/io/input_file.h>
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

const char* const kNeighbourHelp =
    "Number of nearest neighbours whose tangent-plane Delaunay triangulation gives each point its 1-ring. "
    "0 = automatic: 1.2% of the points, between 8 and 30 (the paper's rule). Raise it for noisy scans; "
    "lower it if close-by parts (fingers, claws) get connected.";

// Which points the contraction works on (outliers set aside, a denoised copy): the
// contraction and the skeleton filters ask for them, and the thinning filter must repeat
// them to rebuild the contraction's 1-rings.
void addInputCleaningParameters(RichParameterList& list) {
    list.addParam(RichBool("detectOutliers", pcskeleton::OutlierParameters().detect,
        parameterLabel(Parameter::OutlierDetection),
        "Sets aside, before the 1-rings, points that do not belong to the sampled surface: isolated points and "
        "small sparse clusters, judged against the cloud's own point spacing. They get no node (grey in the "
        "segments layer) and are counted in the log; the layer itself is not changed. Untick to keep every "
        "point, as the paper does."));
    list.addParam(RichInt("denoisePasses", pcskeleton::ContractionParameters().denoisingPasses,
        parameterLabel(Parameter::DenoisingPasses),
        "The 1-rings and the contraction use a copy of the points denoised by this many passes of projection "
        "onto the plane of each point's k nearest neighbours; the nodes and radii still come from the points as "
        "they are. Noise and misaligned scans then leave far fewer spurs and false loops. -1 = automatic: "
        + QString::number(pcskeleton::kPassesForNoisySurface) + " passes if the cloud is noisy (surface noise above "
        + QString::number(pcskeleton::kNoisySurface) + ", given in the log), none if it is clean; 0 = never, as "
        "the paper; 1 to " + QString::number(pcskeleton::kMaximumDenoisingPasses) + " passes always."));
}

void readInputCleaning(const RichParameterList& list, pcskeleton::ContractionParameters& p) {
    p.outliers.detect = list.getBool("detectOutliers");
    p.denoisingPasses = list.getInt("denoisePasses");
}

void addContractionParameters(RichParameterList& list) {
    const pcskeleton::ContractionParameters d;
    list.addParam(RichInt("k", d.neighbourCount, parameterLabel(Parameter::NeighbourCount), kNeighbourHelp));
    list.addParam(RichFloat("contractionWeight", float(d.initialContractionWeight),
        parameterLabel(Parameter::InitialContractionWeight),
        "Strength of the Laplacian (shrinking) term in the first iteration, in the normalised frame where the "
        "cloud's longest side is 1.6. 0 = automatic: 1/(5 S0), S0 being the mean 1-ring size. Too high pulls thin "
        "parts into thick ones (paper Fig. 4d); too low lets tips stick out of the shape (Fig. 4a)."));
    list.addParam(RichFloat("attractionWeight", float(d.initialAttractionWeight),
        parameterLabel(Parameter::InitialAttractionWeight),
        "How strongly points are held at their positions. Acts opposite to W_L0 (paper Fig. 4e-h)."));
    list.addParam(RichFloat("contractionScale", float(d.contractionScale), parameterLabel(Parameter::ContractionScale),
        "W_L is multiplied by this after every iteration. The paper uses 3; use 2 for shapes with thin parts "
        "between thick ones (paper Fig. 10), at the cost of an extra iteration."));
    // An integer on purpose: MeshLab's dialog shows floats with 3 digits, and would read
    // 2048 back as 2050 on Apply.
    list.addParam(RichInt("maxContractionWeight", int(d.maxContractionWeight),
        parameterLabel(Parameter::MaxContractionWeight),
        "Upper limit of the contraction weight, for numerical stability."));
    list.addParam(RichFloat("maxAttractionWeight", float(d.maxAttractionWeight),
        parameterLabel(Parameter::MaxAttractionWeight),
        "Upper limit of a point's attraction weight (it grows as the point's 1-ring shrinks)."));
    list.addParam(RichFloat("laplacianRowLimit", float(d.laplacianRowLimit),
        parameterLabel(Parameter::LaplacianRowLimit),
        "A Laplacian row whose weights add up to more than this is scaled down; guards against the huge "
        "cotangents of nearly flat 1-ring triangles."));
    list.addParam(RichInt("maxIterations", d.maxIterations, parameterLabel(Parameter::MaxIterations),
        "Contraction stops after this many iterations at the latest (most models converge in under 5)."));
    list.addParam(RichFloat("terminationThreshold", float(d.terminationThreshold),
        parameterLabel(Parameter::TerminationThreshold),
        "Contraction stops when the total 1-ring size shrank by less than this fraction of its initial value "
        "in the last iteration."));
    addInputCleaningParameters(list);
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
    readInputCleaning(list, p);
    return p;
}

void addThinningParameters(RichParameterList& list) {
    const pcskeleton::ThinningParameters d;
    list.addParam(RichFloat("sampleRadius", float(d.sampleRadius), parameterLabel(Parameter::NodeSpacing),
        "Radius of the balls that sample the contracted points into skeleton nodes, as a fraction of the "
        "bounding-box diagonal (the paper's 0.02). Larger: fewer nodes, and parts or holes closer than this "
        "merge; smaller: more nodes, and noise may survive as short spurs or tiny loops."));
    list.addParam(RichFloat("linkLimit", float(d.linkLimit), parameterLabel(Parameter::LinkLimit),
        "Neighbouring points whose contracted positions ended more than this many node spacings apart were "
        "pulled to different bones (parts that touch, noise across a gap): they connect their nodes only where "
        "nothing else does, so they close no false loop. Lower it if close parts still get false loops; 0 lets "
        "every neighbour pair connect, as in the paper."));
    list.addParam(RichFloat("gapLimit", float(d.gapLimit), parameterLabel(Parameter::GapLimit),
        "Where the data has a gap across a limb (an occluded stretch of a scan, a missing patch), the skeleton "
        "comes out in pieces. A limb pointing at another piece at most this many node spacings ahead is joined "
        "to it by a bone. Pieces that lie side by side are never joined. Raise it for wider gaps, lower it if "
        "separate objects get joined; 0 joins nothing, as in the paper."));
    list.addParam(RichBool("extendTips", d.extendTips, "Extend tips to the shape's ends",
        "Contraction pulls the ends of limbs inwards, so the skeleton stops short of them. This extends every "
        "limb (not the short spurs) along its direction to where its tip's points end (where their density "
        "along it falls), with a new end node. "
        "Turn it off to get the paper's skeleton exactly."));
    list.addParam(RichBool("recentre", d.recentre, "Re-centre nodes of one-sided parts",
        "Where a node's points cover one side of its bone only (a scan from one side, a hole), their centre lies "
        "on the visible wall: the node moves to the centre of the circle through them, with that circle's "
        "radius. Nodes whose points surround them stay at their centre, as in the paper."));
    list.addParam(RichBool("refine", d.refine, parameterLabel(Parameter::Refinement),
        "Cleans what noise leaves: limbs shorter than the body is thick where they join are absorbed into the "
        "junction, loops smaller than the tube around them collapse to a node, junctions closer than the node "
        "spacing merge, bridges of a handful of points (or a single bone across a gap) between parts that pass "
        "close are cut. On by default: on "
        "noisy and misaligned scans it removes spurs and false loops. Untick "
        "for the paper's skeleton."));
    list.addParam(RichFloat("loopOpening", float(d.narrowLoops.minOpening), parameterLabel(Parameter::LoopOpening),
        "Refinement opens a loop whose hole is narrower than this many tube radii at its bone longest for its "
        "radii, if that bone passes closer than the clearance below to a point: parts that touch, or that noise "
        "joined. Lower it if a real narrow hole is lost; 0 opens none."));
    list.addParam(RichFloat("loopClearance", float(d.narrowLoops.minClearance), parameterLabel(Parameter::LoopClearance),
        "The fraction of its radius within which that bone must pass a point for the loop to be opened: a bone "
        "inside a tube keeps about a radius from its wall. Lower it if a real narrow hole is lost."));
    list.addParam(RichBool("addSegmentsLayer", true, "Add a layer of points coloured by node",
        "Adds a copy of the input points, each coloured by the skeleton node it belongs to (the "
        "correspondence), with the node index in the per-vertex attribute pcs_node. The input layer is "
        "not changed."));
}

// What the thinning filter needs to know of the contraction that made its layer.
pcskeleton::ContractionParameters contractionOfThinning(const RichParameterList& list) {
    pcskeleton::ContractionParameters p;
    p.neighbourCount = list.getInt("k");
    readInputCleaning(list, p);
    return p;
}

pcskeleton::ThinningParameters readThinningParameters(const RichParameterList& list) {
    pcskeleton::ThinningParameters p;
    p.sampleRadius = list.getFloat("sampleRadius");
    p.linkLimit = list.getFloat("linkLimit");
    p.gapLimit = list.getFloat("gapLimit");
    p.extendTips = list.getBool("extendTips");
    p.recentre = list.getBool("recentre");
    p.refine = list.getBool("refine");
    p.narrowLoops.minOpening = list.getFloat("loopOpening");
    p.narrowLoops.minClearance = list.getFloat("loopClearance");
    return p;
}

void addReconstructionParameters(RichParameterList& list) {
    const pcskeleton::ReconstructionParameters d;
    list.addParam(RichInt("resolution", d.resolution, parameterLabel(Parameter::Resolution),
        QString("Grid cells along the longest side (%1 to %2). Finer shows more detail; memory and time "
                "grow with its cube (about 1 GB and 10 s at 256 for a ring-shaped object).")
            .arg(pcskeleton::kMinimumResolution).arg(pcskeleton::kMaximumResolution)));
    list.addParam(RichFloat("smoothWeight", float(d.smoothWeight), parameterLabel(Parameter::SmoothWeight),
        "Weight of the field's smoothness (the integral of its squared Laplacian). Raise it for noisy "
        "scans; lower it to follow the points more closely."));
    list.addParam(RichFloat("surfaceWeight", float(d.surfaceWeight), parameterLabel(Parameter::SurfaceWeight),
        "How strongly the surface passes through the points (field 0 there)."));
    list.addParam(RichFloat("skeletonWeight", float(d.skeletonWeight), parameterLabel(Parameter::SkeletonWeight),
        "How strongly the field equals minus the node radius along the bones. Raise it if the surface "
        "does not bridge a gap the skeleton crosses; the radius sets how thick the bridge is."));
    list.addParam(RichFloat("outsideWeight", float(d.outsideWeight), parameterLabel(Parameter::OutsideWeight),
        "How strongly the field is positive far from the skeleton (a weak hint, the paper's 0.005). Raise "
        "it if the surface bulges into empty space or closes holes the skeleton leaves open."));
    list.addParam(RichFloat("outsideRadii", float(d.outsideRadii), parameterLabel(Parameter::OutsideDistance),
        "Space farther than K node radii from the skeleton counts as outside the shape (the paper's 4). "
        "Lower it to keep gaps open next to thin parts."));
    list.addParam(RichBool("keepSkeletonTopology", d.keepSkeletonTopology, parameterLabel(Parameter::SkeletonTopology),
        "The surface gets exactly the skeleton's topology: one closed part per skeleton part and one handle per "
        "loop. Handles, bridges and islands that the points suggest but the skeleton does not have (noise, "
        "close parts touching) are cut away, and the log says where the largest cut was. Untick for the paper's "
        "plain fit, whose surface may have any topology the points suggest."));
    list.addParam(RichBool("adaptToNoise", d.adaptToNoise, "Weigh noisy points less",
        "Points whose neighbours scatter across the surface by more than a grid cell (scan noise) weigh less in "
        "the fit, so the surface passes through their middle instead of following each bump. Clean parts are "
        "not changed. Untick for the paper's fit, where every point weighs the surface weight w2."));
    list.addParam(RichBool("fitVerticesToPoints", d.fitVerticesToPoints, "Fit the surface to the points",
        "Where there are points, each vertex of the surface moves (by at most a grid cell) onto a smooth local fit "
        "of its nearest points: the field's smoothness rounds thin parts inward by a fraction of a cell, the local "
        "fit does not. Triangles do not change, so neither does the topology. Untick for the field's zero level "
        "set as it is (the paper's)."));
}

pcskeleton::ReconstructionParameters readReconstructionParameters(const RichParameterList& list) {
    pcskeleton::ReconstructionParameters p;
    p.resolution = list.getInt("resolution");
    p.smoothWeight = list.getFloat("smoothWeight");
    p.surfaceWeight = list.getFloat("surfaceWeight");
    p.skeletonWeight = list.getFloat("skeletonWeight");
    p.outsideWeight = list.getFloat("outsideWeight");
    p.outsideRadii = list.getFloat("outsideRadii");
    p.keepSkeletonTopology = list.getBool("keepSkeletonTopology");
    p.adaptToNoise = list.getBool("adaptToNoise");
    p.fitVerticesToPoints = list.getBool("fitVerticesToPoints");
    return p;
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

}  // namespace

FilterPCSkeletonPlugin::FilterPCSkeletonPlugin() {
    typeList = {FP_CONTRACT_POINT_CLOUD,          FP_COMPUTE_SKELETON,       FP_SKELETON_FROM_CONTRACTED,
                FP_EXPORT_SKELETON,               FP_DELETE_SELECTED_NODES,  FP_CONNECT_SELECTED_NODES,
                FP_MERGE_SELECTED_NODES,          FP_SET_RADIUS_OF_SELECTED_NODES, FP_RECONSTRUCT_FROM_SKELETON};
    for (int type : typeList) actionList.push_back(new QAction(filterName(type), this));
}

QString FilterPCSkeletonPlugin::pluginName() const { return "FilterPCSkeleton"; }

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
    }
    return {};
}

QString FilterPCSkeletonPlugin::filterInfo(int filter) const {
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
                "contraction exactly).") + kPaperReference;
        case FP_COMPUTE_SKELETON:
            return QString(
                "Computes the curve skeleton of the current layer's points: Laplacian contraction, then "
                "farthest-point sampling of the contracted points, connection through the points' 1-rings and "
                "collapse of every triangle (the shape's loops survive), then each node moves to the centre of "
                "its points, and limbs are extended to their ends. Adds a skeleton layer (vertices = nodes, "
                "edges = bones, radius in vertex quality and in the attribute pcs_radius), and logs a quality "
                "report: topology, convergence, and warnings naming the parameter to change. The input layer is "
                "not changed. Save the skeleton with Export Skeleton: MeshLab's own PLY export drops edges.") +
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
            addContractionParameters(parameters);
            parameters.addParam(RichInt("iterationsToRun", 0, "Iterations to run",
                "Run at most this many iterations, to watch the cloud contract step by step "
                "(0 = until contraction stops)."));
            parameters.addParam(RichBool("keepEveryIteration", false, "One layer per iteration",
                "Add a layer after every iteration instead of only the final one."));
            break;
        case FP_COMPUTE_SKELETON:
            addContractionParameters(parameters);
            addThinningParameters(parameters);
            parameters.addParam(RichBool("addContractedLayer", false, "Add the contracted points layer",
                "Also adds the contracted points as a layer, e.g. to thin them again later with other settings "
                "(Skeleton from Contracted Points)."));
            parameters.addParam(RichBool("fullResolution", false, "Full resolution",
                QString("Contract every point. By default a layer of more than %1 points is contracted through a "
                        "well-spread subsample of %1 (one per cube of a grid), which takes seconds instead of minutes "
                        "at a million points and needs far less memory; every point still gets its node, and the "
                        "radii come from all points.").arg(pcskeleton::ResolutionParameters{}.maxContractedPoints)));
            parameters.addParam(RichBool("paperPipeline", false, "The paper's pipeline only",
                "Exactly the paper's steps: no outlier detection, denoising, re-centring, refinement, tip "
                "extension, stretched-link limit or subsample, whatever is set above. For comparison with the paper and other implementations of it."));
            break;
        case FP_SKELETON_FROM_CONTRACTED:
            parameters.addParam(layerParameter("sourceLayer", likelySourceOf(md, md.mm()), md, "Original points",
                "The layer that was contracted: its points give the 1-rings, the node positions and the radii."));
            parameters.addParam(RichInt("k", 0, parameterLabel(Parameter::NeighbourCount),
                QString(kNeighbourHelp) + " Use the value the contraction used."));
            addInputCleaningParameters(parameters);
            addThinningParameters(parameters);
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
            addReconstructionParameters(parameters);
            break;
        }
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
    const pcskeleton::ContractionParameters settings = readContractionParameters(parameters);
    const int iterationsToRun = parameters.getInt("iterationsToRun");
    const bool keepEveryIteration = parameters.getBool("keepEveryIteration");
    if (iterationsToRun < 0) {
        failure_ = "Iterations to run must be 0 (until contraction stops) or positive.";
        return false;
    }
    const pcskeleton::ProgressCallback progress = progressOf(cb);
    pcskeleton::LaplacianContraction contraction(input.points, settings, pcskeleton::progressRange(progress, 0, 30));
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
    if (addSegments) addSegmentsLayer(md, source, input, result.skeleton, derivedLabel(source, "segments"));
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
    pcskeleton::SkeletonParameters pipeline{readContractionParameters(parameters), readThinningParameters(parameters), {}};
    if (parameters.getBool("fullResolution")) pipeline.resolution.maxContractedPoints = 0;
    if (parameters.getBool("paperPipeline")) pipeline.keepToThePaper();
    const pcskeleton::ContractionParameters& settings = pipeline.contraction;
    const pcskeleton::ThinningParameters& thinning = pipeline.thinning;
    const pcskeleton::ProgressCallback progress = progressOf(cb);
    pcskeleton::checkThinningParameters(thinning);  // before the contraction, not after it

    const pcskeleton::ContractionInput work(input.points, pipeline.resolution, settings.outliers,
                                            pcskeleton::progressRange(progress, 0, 10));
    if (work.subsampled()) {
        writeLog(*this, "Multi-resolution: %zu of the %zu points contracted (one per cube of side %.4g); every point gets the node "
            "of its cube's point.", work.points().size(), input.points.size(), work.subsample().cellSize);
    }
    pcskeleton::LaplacianContraction contraction(work.points(), settings, pcskeleton::progressRange(progress, 10, 25));
    logContractionStart(source, contraction, work.points().size());
    const int done = contract(contraction, settings.maxIterations, [&](int iteration) {
        pcskeleton::report(progress, 25 + 65 * iteration / settings.maxIterations, "Contracting");
    });
    writeLog(*this, "Contraction: %d iteration(s), %s.", done, pcskeleton::describe(contraction.stopReason()).c_str());

    pcskeleton::SkeletonResult result =
        pcskeleton::skeletonFromContraction(contraction, thinning, pcskeleton::progressRange(progress, 90, 100));
    work.carryToAllPoints(result);
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
    const pcskeleton::SkeletonResult result = pcskeleton::skeletonFromContractedPoints(
        input.points, contracted, contractionOfThinning(parameters), readThinningParameters(parameters), progressOf(cb));
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
    for (const MeshModel* m : layersOf(md)) {
        if (!m->fullName().isEmpty() && pcskeleton::sameFile(m->fullName().toStdString(), fileName.toStdString())) {
            failure_ = QString("Cannot write '%1': it is the file of the open layer '%2', which is never "
                                   "overwritten. Choose another name.").arg(fileName, m->label());
            return false;
        }
    }
    if (QFileInfo::exists(fileName) && !parameters.getBool("overwrite")) {
        failure_ = QString("Cannot write '%1': the file exists already. Choose another name, or tick "
                               "'Replace an existing file'.").arg(fileName);
        return false;
    }
    const pcskeleton::SkeletonGraph skeleton = readSkeletonLayer(layer);
    pcskeleton::writeSkeleton(skeleton, fileName.toStdString());
    writeLog(*this, "Skeleton '%s' written to '%s': %s.", qUtf8Printable(layer.label()),
        qUtf8Printable(QFileInfo(fileName).absoluteFilePath()),
        pcskeleton::describe(pcskeleton::analyseTopology(skeleton)).c_str());
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
        addReconstructionLayer(md, *points, *skeleton, readReconstructionParameters(parameters), progressOf(cb));
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
