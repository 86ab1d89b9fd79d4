// How pcskeleton's data lives in MeshLab layers: the conversions between CMeshO and the
// vcg_ext types, shared by the filters (and the skeleton editor).
//
// A skeleton layer: vertices = nodes, edges = bones, no faces. The radius is the vertex
// quality (MeshLab shows, colours and saves it) and the per-vertex attribute pcs_radius.
// The per-mesh attribute pcs_correspondence holds, for each vertex slot of the source
// point layer, the node it belongs to (-1: none), and pcs_source_layer that layer's id.
#pragma once

#include "meshlab_compat.h"

#include <pcskeleton/skeleton/skeleton_graph.h>

#include <QString>

namespace pcskeleton::meshlab {

extern const char* const kInputIndexAttribute;      // per vertex, int: source vertex of a contracted point
extern const char* const kRadiusAttribute;          // per vertex, float: node radius
extern const char* const kNodeAttribute;            // per vertex, int: a point's node (segments layer)
extern const char* const kBranchAttribute;          // per vertex, int: a point's branch (branches layer)
extern const char* const kInferredAttribute;        // per edge, unsigned char: 1 for a bone the data does not show
extern const char* const kCorrespondenceAttribute;  // per mesh, std::vector<int>
extern const char* const kSourceLayerAttribute;     // per mesh, int: MeshModel id

// The live vertices of a layer as points; faces are ignored (polygon soups work).
// Throws InvalidInput when the layer lies so far from the origin for its size that
// MeshLab's single-precision coordinates have merged its points (see the .cpp).
struct LayerPoints {
    PointList points;
    std::vector<int> vertexIndex;  // slot in mesh.vert of each point
};
LayerPoints collectPoints(const MeshModel& layer);

// "<source base name> <what>". MeshLab's layer list cuts labels at the first dot, hence
// the base name ("bunny.ply contracted" would show as "bunny").
QString derivedLabel(const MeshModel& source, const QString& what);

// A point layer with `positions` (one per point of `input`), each vertex remembering its
// source vertex in pcs_input_index; vertex colours are copied when the source has them.
// Reads a layer made by the contraction filter: fills `input` with the live points of
// `source` and returns the contracted position of each. Throws InvalidInput when
// `contracted` was not made by that filter, or not from `source`.
PointList readContractedLayer(const MeshModel& contracted, const MeshModel* source, LayerPoints& input);

MeshModel* addPointLayer(MeshDocument& md, const MeshModel& source, const LayerPoints& input,
                         const PointList& positions, const QString& label);

MeshModel* addSkeletonLayer(MeshDocument& md, const MeshModel& source, const LayerPoints& input,
                            const SkeletonGraph& skeleton, const QString& label);

// A copy of the points of `input`, each coloured by its label (grey for -1) and carrying it
// as the per-vertex int attribute `attribute`; labels run from 0 to labelCount - 1.
MeshModel* addLabelledPointLayer(MeshDocument& md, const LayerPoints& input, const std::vector<int>& labels,
                                 int labelCount, const char* attribute, const QString& label);

// A copy of the source points, each coloured by its node and carrying pcs_node.
MeshModel* addSegmentsLayer(MeshDocument& md, const LayerPoints& input,
                            const SkeletonGraph& skeleton, const QString& label);

// The layer a skeleton (or contracted) layer was computed from, if it is still open
// (pcs_source_layer); nullptr otherwise.
MeshModel* sourceLayerOf(MeshDocument& md, const MeshModel& layer);

// Empty when `layer` can be read as a skeleton, else the reason, meant for the user.
QString notASkeletonReason(const MeshModel& layer);
// The layer's live vertices and edges as a graph (nodes renumbered densely). pointNode is
// the layer's pcs_correspondence (indexed by the source layer's vertex slots), empty when
// the layer has none, e.g. a skeleton opened from a file.
SkeletonGraph readSkeletonLayer(const MeshModel& layer);
// Replaces the layer's vertices and edges by `skeleton`, in the conventions above; the
// correspondence attribute is replaced when `skeleton.pointNode` is not empty. The layer
// keeps its label, its source layer link and its place in the document.
void writeSkeletonLayer(MeshModel& layer, const SkeletonGraph& skeleton);

// The selected live vertices, numbered as readSkeletonLayer numbers the nodes.
std::vector<int> selectedNodes(const MeshModel& layer);
// Selects exactly these nodes (indices as above).
void selectNodes(MeshModel& layer, const std::vector<int>& nodes);

}  // namespace pcskeleton::meshlab
