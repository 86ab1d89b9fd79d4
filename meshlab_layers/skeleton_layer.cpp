#include "skeleton_layer.h"

#include <pcskeleton/contraction/point_cloud_input.h>

#include <limits>

#include <vcg/complex/allocate.h>

#include <QFileInfo>

namespace pcskeleton::meshlab {

const char* const kInputIndexAttribute = "pcs_input_index";
const char* const kRadiusAttribute = "pcs_radius";
const char* const kInferredAttribute = "pcs_inferred";
const char* const kNodeAttribute = "pcs_node";
const char* const kBranchAttribute = "pcs_branch";
const char* const kCorrespondenceAttribute = "pcs_correspondence";
const char* const kSourceLayerAttribute = "pcs_source_layer";

using Allocator = vcg::tri::Allocator<CMeshO>;

namespace {

CMeshO::CoordType toMeshLab(const Point& p) { return CMeshO::CoordType(p.x(), p.y(), p.z()); }

MeshModel* addPointCopy(MeshDocument& md, const LayerPoints& input,
                        const PointList& positions, const QString& label) {
    MeshModel* layer = md.addNewMesh("", label, true);
    CMeshO& out = layer->cm;
    auto vertex = Allocator::AddVertices(out, positions.size());
    auto inputIndex = Allocator::GetPerVertexAttribute<int>(out, kInputIndexAttribute);
    for (std::size_t i = 0; i < positions.size(); ++i, ++vertex) {
        vertex->P() = toMeshLab(positions[i]);
        inputIndex[vertex] = input.vertexIndex[i];
    }
    return layer;
}

}  // namespace

namespace {

// MeshLab keeps coordinates in single precision: 1e7 from the origin, neighbouring values
// are about 1.2 apart, so a scan 10 across in georeferenced coordinates is merged onto a
// few positions when it is loaded, and translating it in MeshLab cannot bring the lost
// digits back. Refused when fewer than this many representable steps span the layer.
constexpr double kMinimumStepsAcrossLayer = 1000;

void refuseCollapsedCoordinates(const MeshModel& layer, const PointList& points) {
    if (points.empty()) return;
    const Eigen::AlignedBox3d box = pcskeleton::boundingBox(points);
    const double farthest = std::max(box.min().cwiseAbs().maxCoeff(), box.max().cwiseAbs().maxCoeff());
    const double step = farthest * std::numeric_limits<float>::epsilon();
    const double size = box.sizes().maxCoeff();
    if (step == 0 || size == 0 || size >= kMinimumStepsAcrossLayer * step) return;  // one point: the library says
    throw InvalidInput(QString("Layer '%1' lies %2 from the origin but is only %3 across. MeshLab stores coordinates "
                               "in single precision: that far out, neighbouring values are %4 apart, so its points "
                               "were merged onto a coarse grid when the file was loaded. Move the data near the "
                               "origin before opening it in MeshLab (subtract its centre where it is produced), or "
                               "run the pcskeleton command-line tool, which reads files in double precision.")
                           .arg(layer.label()).arg(farthest, 0, 'g', 3).arg(size, 0, 'g', 3).arg(step, 0, 'g', 2)
                           .toStdString());
}

}  // namespace

LayerPoints collectPoints(const MeshModel& layer) {
    const CMeshO& mesh = layer.cm;
    LayerPoints input;
    input.points.reserve(mesh.vn);
    input.vertexIndex.reserve(mesh.vn);
    for (std::size_t i = 0; i < mesh.vert.size(); ++i) {
        const CVertexO& v = mesh.vert[i];
        if (v.IsD()) continue;
        input.points.emplace_back(v.cP()[0], v.cP()[1], v.cP()[2]);
        input.vertexIndex.push_back(int(i));
    }
    refuseCollapsedCoordinates(layer, input.points);
    return input;
}

PointList readContractedLayer(const MeshModel& contracted, const MeshModel* sourceLayer, LayerPoints& input) {
    CMeshO& m = const_cast<CMeshO&>(contracted.cm);  // vcglib's attribute lookup is not const
    auto inputIndex = Allocator::FindPerVertexAttribute<int>(m, kInputIndexAttribute);
    if (!Allocator::IsValidHandle(m, inputIndex)) {
        throw InvalidInput(QString("Layer '%1' was not made by Contract Point Cloud (Laplacian): it has no "
                                   "pcs_input_index attribute. Select the contracted layer, or use Compute Curve "
                                   "Skeleton on the original points.").arg(contracted.label()).toStdString());
    }
    if (sourceLayer == nullptr || sourceLayer == &contracted) {
        throw InvalidInput("Choose as original points the layer that was contracted, not the contracted layer itself.");
    }
    const MeshModel& source = *sourceLayer;
    input = collectPoints(source);
    std::vector<int> pointOfVertex(source.cm.vert.size(), -1);
    for (std::size_t i = 0; i < input.vertexIndex.size(); ++i) pointOfVertex[input.vertexIndex[i]] = int(i);
    PointList positions(input.points.size());
    std::vector<bool> seen(input.points.size(), false);
    for (std::size_t v = 0; v < m.vert.size(); ++v) {
        const CVertexO& vertex = m.vert[v];
        if (vertex.IsD()) continue;
        const int sourceVertex = inputIndex[v];
        const int point = sourceVertex >= 0 && sourceVertex < int(pointOfVertex.size()) ? pointOfVertex[sourceVertex] : -1;
        if (point < 0) {
            throw InvalidInput(QString("Layer '%1' does not match '%2': contracted point %3 refers to vertex %4, "
                                       "which '%2' does not have. Choose the layer that was contracted.")
                                   .arg(contracted.label(), source.label()).arg(v).arg(sourceVertex).toStdString());
        }
        positions[point] = Point(vertex.cP()[0], vertex.cP()[1], vertex.cP()[2]);
        seen[point] = true;
    }
    const auto missing = std::count(seen.begin(), seen.end(), false);
    if (missing > 0) {
        throw InvalidInput(QString("Layer '%1' lacks %2 of the %3 points of '%4': it was made from another layer, "
                                   "or points were deleted since. Contract '%4' again.")
                               .arg(contracted.label()).arg(missing).arg(input.points.size()).arg(source.label())
                               .toStdString());
    }
    return positions;
}

QString derivedLabel(const MeshModel& source, const QString& what) {
    return QString("%1 %2").arg(QFileInfo(source.label()).completeBaseName(), what);
}

MeshModel* addPointLayer(MeshDocument& md, const MeshModel& source, const LayerPoints& input,
                         const PointList& positions, const QString& label) {
    MeshModel* layer = addPointCopy(md, input, positions, label);
    if (source.hasDataMask(MeshModel::MM_VERTCOLOR)) {
        layer->updateDataMask(MeshModel::MM_VERTCOLOR);
        for (std::size_t i = 0; i < input.vertexIndex.size(); ++i) {
            layer->cm.vert[i].C() = source.cm.vert[input.vertexIndex[i]].cC();
        }
    }
    updateBoxAndNormals(*layer);
    return layer;
}

MeshModel* addSkeletonLayer(MeshDocument& md, const MeshModel& source, const LayerPoints& input,
                            const SkeletonGraph& skeleton, const QString& label) {
    MeshModel* layer = md.addNewMesh("", label, true);
    SkeletonGraph bySlot = skeleton;
    bySlot.pointNode.assign(source.cm.vert.size(), -1);
    for (std::size_t i = 0; i < input.vertexIndex.size(); ++i) bySlot.pointNode[input.vertexIndex[i]] = skeleton.pointNode[i];
    writeSkeletonLayer(*layer, bySlot);
    Allocator::GetPerMeshAttribute<int>(layer->cm, kSourceLayerAttribute)() = source.id();
    return layer;
}

// MeshLab draws a new layer of edges as thin lines, of a fixed dark grey unless its vertices
// have colours, and its vertices as points in their colour; a filter cannot choose the
// lines' width (docs/meshlab.md says where a user does). Coloured vertices make the nodes
// stand out over a scan and tint the bones. Green: neither the grey or white of most scans,
// nor the yellow and red of the Edit Skeleton tool's nodes.
const vcg::Color4b kSkeletonColour(20, 220, 60, 255);

void writeSkeletonLayer(MeshModel& layer, const SkeletonGraph& skeleton) {
    CMeshO& out = layer.cm;
    // Stale per-vertex values must not survive into the new vertices.
    auto oldRadius = Allocator::FindPerVertexAttribute<float>(out, kRadiusAttribute);
    if (Allocator::IsValidHandle(out, oldRadius)) Allocator::DeletePerVertexAttribute(out, oldRadius);
    auto oldInferred = Allocator::FindPerEdgeAttribute<unsigned char>(out, kInferredAttribute);
    if (Allocator::IsValidHandle(out, oldInferred)) Allocator::DeletePerEdgeAttribute(out, oldInferred);
    out.Clear();
    layer.updateDataMask(MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR);
    auto vertex = Allocator::AddVertices(out, skeleton.nodeCount());
    auto radius = Allocator::GetPerVertexAttribute<float>(out, kRadiusAttribute);
    for (std::size_t n = 0; n < skeleton.nodeCount(); ++n, ++vertex) {
        vertex->P() = toMeshLab(skeleton.nodes[n]);
        vertex->Q() = radius[vertex] = float(skeleton.radii[n]);
        vertex->C() = kSkeletonColour;
    }
    for (const Edge& e : skeleton.edges) Allocator::AddEdge(out, e[0], e[1]);
    if (!skeleton.inferred.empty()) {
        auto inferred = Allocator::GetPerEdgeAttribute<unsigned char>(out, kInferredAttribute);
        const std::vector<char> flags = inferredFlags(skeleton);
        for (std::size_t e = 0; e < flags.size(); ++e) inferred[e] = static_cast<unsigned char>(flags[e]);
    }
    if (!skeleton.pointNode.empty()) {
        Allocator::GetPerMeshAttribute<std::vector<int>>(out, kCorrespondenceAttribute)() = skeleton.pointNode;
    }
    updateBoxAndNormals(layer);
    // Nodes have no surface, hence no normal (MeshLab leaves them zero, and lit points with
    // a zero normal come out nearly black): facing MeshLab's first view, they are lit there.
    for (CVertexO& v : out.vert) v.N() = CMeshO::CoordType(0, 0, 1);
}

MeshModel* addLabelledPointLayer(MeshDocument& md, const LayerPoints& input, const std::vector<int>& labels,
                                 int labelCount, const char* attribute, const QString& label) {
    MeshModel* layer = addPointCopy(md, input, input.points, label);
    layer->updateDataMask(MeshModel::MM_VERTCOLOR);
    auto value = Allocator::GetPerVertexAttribute<int>(layer->cm, attribute);
    for (std::size_t i = 0; i < input.points.size(); ++i) {
        CVertexO& v = layer->cm.vert[i];
        value[v] = labels[i];
        v.C() = labels[i] < 0 ? vcg::Color4b(vcg::Color4b::Gray)
                              : vcg::Color4b::Scatter(std::max(1, labelCount), labels[i], .6f, .9f);
    }
    updateBoxAndNormals(*layer);
    return layer;
}

MeshModel* addSegmentsLayer(MeshDocument& md, const LayerPoints& input,
                            const SkeletonGraph& skeleton, const QString& label) {
    return addLabelledPointLayer(md, input, skeleton.pointNode, int(skeleton.nodeCount()), kNodeAttribute, label);
}

MeshModel* sourceLayerOf(MeshDocument& md, const MeshModel& layer) {
    CMeshO& m = const_cast<CMeshO&>(layer.cm);  // vcglib's attribute lookup is not const
    auto source = Allocator::FindPerMeshAttribute<int>(m, kSourceLayerAttribute);
    return Allocator::IsValidHandle(m, source) ? md.getMesh(source()) : nullptr;
}

QString notASkeletonReason(const MeshModel& layer) {
    CMeshO& m = const_cast<CMeshO&>(layer.cm);  // vcglib's attribute lookup is not const
    if (m.vn == 0) return QString("Layer '%1' is empty: it is not a skeleton.").arg(layer.label());
    if (m.fn > 0) {
        return QString("Layer '%1' has faces: it is a mesh, not a skeleton. Select a skeleton layer (made by "
                       "Compute Curve Skeleton, or a PLY/OBJ file with edges).").arg(layer.label());
    }
    const bool hasRadius = Allocator::IsValidHandle(m, Allocator::FindPerVertexAttribute<float>(m, kRadiusAttribute));
    if (m.en == 0 && !hasRadius) {
        return QString("Layer '%1' has no edges: it is a point cloud, not a skeleton. Run Compute Curve "
                       "Skeleton on it first, or open a skeleton PLY/OBJ file with edges.").arg(layer.label());
    }
    return {};
}

SkeletonGraph readSkeletonLayer(const MeshModel& layer) {
    CMeshO& m = const_cast<CMeshO&>(layer.cm);  // vcglib's attribute lookup is not const
    auto radius = Allocator::FindPerVertexAttribute<float>(m, kRadiusAttribute);
    const bool hasRadius = Allocator::IsValidHandle(m, radius);
    SkeletonGraph skeleton;
    std::vector<int> node(m.vert.size(), -1);
    for (std::size_t i = 0; i < m.vert.size(); ++i) {
        const CVertexO& v = m.vert[i];
        if (v.IsD()) continue;
        node[i] = int(skeleton.nodes.size());
        skeleton.nodes.emplace_back(v.cP()[0], v.cP()[1], v.cP()[2]);
        skeleton.radii.push_back(hasRadius ? radius[i] : v.cQ());
    }
    auto inferred = Allocator::FindPerEdgeAttribute<unsigned char>(m, kInferredAttribute);
    const bool hasInferred = Allocator::IsValidHandle(m, inferred);
    for (std::size_t i = 0; i < m.edge.size(); ++i) {
        const CEdgeO& e = m.edge[i];
        if (e.IsD()) continue;
        const int a = node[vcg::tri::Index(m, e.cV(0))], b = node[vcg::tri::Index(m, e.cV(1))];
        if (a < 0 || b < 0) continue;
        skeleton.edges.push_back({a, b});
        if (hasInferred && inferred[i]) skeleton.inferred.push_back({a, b});
    }
    normalizeEdges(skeleton.edges);
    keepInferredWithinEdges(skeleton);
    auto correspondence = Allocator::FindPerMeshAttribute<std::vector<int>>(m, kCorrespondenceAttribute);
    if (Allocator::IsValidHandle(m, correspondence)) {
        // Entries are vertex slots of this layer, stale if vertices were deleted since.
        for (int vertexSlot : correspondence()) {
            const bool live = vertexSlot >= 0 && vertexSlot < int(node.size());
            skeleton.pointNode.push_back(live ? node[vertexSlot] : -1);
        }
    }
    return skeleton;
}

std::vector<int> selectedNodes(const MeshModel& layer) {
    std::vector<int> selected;
    int node = 0;
    for (const CVertexO& v : layer.cm.vert) {
        if (v.IsD()) continue;
        if (v.IsS()) selected.push_back(node);
        ++node;
    }
    return selected;
}

void selectNodes(MeshModel& layer, const std::vector<int>& nodes) {
    std::vector<bool> wanted(layer.cm.vert.size(), false);
    for (int n : nodes) {
        if (n >= 0 && n < int(wanted.size())) wanted[n] = true;
    }
    int node = 0;
    for (CVertexO& v : layer.cm.vert) {
        if (v.IsD()) continue;
        if (wanted[node++]) v.SetS();
        else v.ClearS();
    }
}

}  // namespace pcskeleton::meshlab
