// How the Edit Skeleton tool draws over MeshLab's view: bones, node markers, the radius
// field and the rubber band. Immediate-mode OpenGL, as MeshLab's own edit tools draw in
// their decorate step; the caller has applied the layer's matrix.
#pragma once

#include <pcskeleton/skeleton/skeleton_graph.h>

#include <QPoint>

#include <vector>

class QWidget;

namespace pcskeleton::edit {

// `nodes` are the positions to draw (the graph's, or moved by a drag in progress).
void drawBones(const SkeletonGraph& graph, const PointList& nodes, const std::vector<bool>& selected);
void drawNodes(const PointList& nodes, const std::vector<bool>& selected, double markerSize);
// Translucent spheres and cones of the nodes' radii: where the reconstruction will put the surface.
void drawRadiusField(const SkeletonGraph& graph, const PointList& nodes);
// The selection rectangle between two widget positions, in window coordinates.
void drawRubberBand(const QWidget& view, const QPoint& from, const QPoint& to);

}  // namespace pcskeleton::edit
