#include "pcskeleton/skeleton/skeleton_embedding.h"

namespace pcskeleton {

SkeletonGraph embedSkeleton(const ThinnedGraph& graph, const NormalizedCloud& cloud) {
    const std::size_t nodeCount = graph.nodes.size();
    PointList centre(nodeCount, Point::Zero());
    std::vector<int> members(nodeCount, 0);
    for (std::size_t i = 0; i < cloud.points.size(); ++i) {
        centre[graph.owner[i]] += cloud.points[i];
        ++members[graph.owner[i]];
    }
    for (std::size_t n = 0; n < nodeCount; ++n) centre[n] /= std::max(members[n], 1);

    const std::vector<double> radius = meanDistanceToNodes(cloud.points, graph.owner, centre);

    SkeletonGraph skeleton;
    skeleton.edges = graph.edges;
    skeleton.nodes.reserve(nodeCount);
    skeleton.radii.reserve(nodeCount);
    for (std::size_t n = 0; n < nodeCount; ++n) {
        skeleton.nodes.push_back(cloud.toInputFrame(centre[n]));
        skeleton.radii.push_back(radius[n] / cloud.scale);
    }
    skeleton.pointNode.reserve(cloud.inputSize());
    for (int unique : cloud.uniqueIndex) skeleton.pointNode.push_back(unique >= 0 ? graph.owner[unique] : -1);
    fillMissingRadii(skeleton);  // a node owning one point (an outlier) has radius 0
    return skeleton;
}

}  // namespace pcskeleton
