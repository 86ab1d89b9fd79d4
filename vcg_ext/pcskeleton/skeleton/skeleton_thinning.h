// Step 4 of the paper (Sec. III-B): from contracted points to a 1-D graph.
//
// 1. Farthest-point sampling of the contracted points until every point lies within
//    `radius` of a sample; each point belongs to its nearest sample.
// 2. Two samples are connected when some of their points are 1-ring neighbours; not the
//    paper's: a link that contraction stretched (its points ended farther apart than a
//    limit, and twice as far as they started) connects only samples nothing else connects.
// 3. The shortest edge lying on a triangle is collapsed to its midpoint (points merged)
//    until no triangle is left. Longer cycles, the shape's loops, survive.
#pragma once

#include "pcskeleton/contraction/one_ring.h"
#include "pcskeleton/core/progress.h"
#include "pcskeleton/skeleton/skeleton_graph.h"

namespace pcskeleton {

struct SampledPoints {
    std::vector<int> samples;  // indices of the sampled points, in sampling order
    std::vector<int> owner;    // per point: index into `samples` of its nearest sample
};

// Farthest-point sampling stopped when the farthest point is within `radius` of a sample.
// Starts from the point farthest from the centroid, so extremities get samples.
SampledPoints farthestPointSampling(const PointList& points, double radius);

// Edges between owners of 1-ring neighbours. A link is stretched when its points ended
// farther apart than `maxLinkLength` and than twice their `original` distance; stretched
// links are used, shortest first, only to join samples not joined otherwise (infinity:
// every link connects, the paper's rule).
std::vector<Edge> connectByOneRings(const OneRings& rings, const std::vector<int>& owner, const PointList& original,
                                    const PointList& contracted, double maxLinkLength);

struct ThinnedGraph {
    PointList nodes;           // same frame as the contracted points
    std::vector<Edge> edges;
    std::vector<int> owner;    // per point: its node
};

// Collapses triangle edges, shortest first, until the graph has no triangle.
// `graph.owner` is updated; nodes are renumbered densely.
void collapseTriangles(ThinnedGraph& graph);

// Steps 1-3 on contracted points whose 1-rings are `rings`, with the stretched-link rule
// of connectByOneRings.
ThinnedGraph thinContractedPoints(const PointList& original, const PointList& contracted, const OneRings& rings,
                                  double radius, double maxLinkLength, const ProgressCallback& progress = {});

}  // namespace pcskeleton
