// Section V in MeshLab terms: a point layer and a skeleton layer in, a new mesh layer
// out. Shared by the "Reconstruct Surface from Skeleton" filter and the skeleton editor's
// button, so that both check the same things and make the same layer.
#pragma once

#include "meshlab_compat.h"

#include <pcskeleton/core/progress.h>
#include <pcskeleton/reconstruction/skeleton_reconstruction.h>

namespace pcskeleton::meshlab {

// Sensible dialog defaults from the current layer: the skeleton (the current layer if it
// is one, else a skeleton computed from it, else any skeleton) and its points (the
// skeleton's source, else the current layer if it is not a skeleton, else any other).
MeshModel* defaultSkeletonLayer(MeshDocument& md);
MeshModel* defaultPointsLayer(MeshDocument& md);

struct ReconstructedLayer {
    MeshModel* layer = nullptr;
    ReconstructionReport report;
};

// Adds "<points> reconstruction" (made current if asked). Throws InvalidInput, naming the layer and
// what to do, when `points` is empty or a skeleton, `skeleton` is not a skeleton, or the
// reconstruction refuses the data. Neither input layer is changed.
ReconstructedLayer addReconstructionLayer(MeshDocument& md, const MeshModel& points, const MeshModel& skeleton,
                                          const ReconstructionParameters& parameters,
                                          const ProgressCallback& progress = {}, bool makeCurrent = true);

}  // namespace pcskeleton::meshlab
