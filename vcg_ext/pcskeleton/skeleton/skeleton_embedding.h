// Step 5 of the paper (end of Sec. III): the thinned graph is placed back inside the
// shape. Each node moves to the centre of its corresponding input points (contracted
// points can sit off-centre); its radius is their mean distance to that centre
// (a node with a single point takes its neighbours' radius: see fillMissingRadii).
#pragma once

#include "pcskeleton/contraction/point_cloud_input.h"
#include "pcskeleton/skeleton/skeleton_graph.h"
#include "pcskeleton/skeleton/skeleton_thinning.h"

namespace pcskeleton {

// `graph.owner` indexes `cloud.points`; the result is in the input's frame, with one
// correspondence entry per input point (duplicates follow their twin).
SkeletonGraph embedSkeleton(const ThinnedGraph& graph, const NormalizedCloud& cloud);

}  // namespace pcskeleton
