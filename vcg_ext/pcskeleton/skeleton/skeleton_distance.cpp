#include "pcskeleton/skeleton/skeleton_distance.h"

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Simple_cartesian.h>

namespace pcskeleton {

namespace {
using Kernel = CGAL::Simple_cartesian<double>;
using Segment3 = Kernel::Segment_3;
using SegmentIterator = std::vector<Segment3>::const_iterator;
using Primitive = CGAL::AABB_segment_primitive<Kernel, SegmentIterator>;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Kernel::Point_3 toCgal(const Point& p) { return {p.x(), p.y(), p.z()}; }
}  // namespace

struct SkeletonDistance::Tree {
    std::vector<Segment3> segments;
    std::vector<std::array<double, 2>> endRadii;  // radius at each segment's source and target
    AabbTree tree;
};

SkeletonDistance::SkeletonDistance(const SkeletonGraph& skeleton) : tree_(std::make_unique<Tree>()) {
    if (skeleton.nodes.empty()) throw CallerError("SkeletonDistance: the skeleton has no nodes.");
    if (skeleton.radii.size() != skeleton.nodes.size()) throw CallerError("SkeletonDistance: the skeleton needs one radius per node.");
    // Nodes without a bone, and bones of length 0, become tiny segments: one query type for all.
    double extent = 0;
    for (const Point& p : skeleton.nodes) extent = std::max(extent, (p - skeleton.nodes[0]).cwiseAbs().maxCoeff());
    const Point tiny(std::max(extent, 1.0) * 1e-9, 0, 0);
    auto addSegment = [&](int a, int b) {
        Point to = skeleton.nodes[b];
        if ((to - skeleton.nodes[a]).norm() <= tiny.x()) to = skeleton.nodes[a] + tiny;
        tree_->segments.emplace_back(toCgal(skeleton.nodes[a]), toCgal(to));
        tree_->endRadii.push_back({skeleton.radii[a], skeleton.radii[b]});
    };
    const std::vector<int> degree = nodeDegrees(skeleton.nodeCount(), skeleton.edges);
    for (const Edge& e : skeleton.edges) addSegment(e[0], e[1]);
    for (int n = 0; n < int(skeleton.nodeCount()); ++n)
        if (degree[n] == 0) addSegment(n, n);
    tree_->tree.insert(tree_->segments.cbegin(), tree_->segments.cend());
    tree_->tree.build();
    tree_->tree.accelerate_distance_queries();
    // The distance-query search tree is built lazily by the first query: do it here, so
    // that concurrent queries only read.
    tree_->tree.closest_point(toCgal(skeleton.nodes[0]));
}

SkeletonDistance::~SkeletonDistance() = default;

SkeletonProximity SkeletonDistance::nearest(const Point& p) const {
    const auto hit = tree_->tree.closest_point_and_primitive(toCgal(p));
    const Kernel::Point_3& q = hit.first;
    const std::size_t segment = std::size_t(hit.second - tree_->segments.cbegin());
    const Segment3& s = tree_->segments[segment];
    const double length = std::sqrt(s.squared_length());
    const double t = std::min(1.0, std::sqrt(CGAL::squared_distance(s.source(), q)) / length);
    const auto& r = tree_->endRadii[segment];
    return {std::sqrt(CGAL::squared_distance(toCgal(p), q)), (1 - t) * r[0] + t * r[1]};
}

}  // namespace pcskeleton
