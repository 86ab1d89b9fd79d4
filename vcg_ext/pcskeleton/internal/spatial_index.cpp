#include "pcskeleton/internal/spatial_index.h"

#include "pcskeleton/internal/parallel_sort.h"

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>
#include <boost/iterator/counting_iterator.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <limits>
#include <utility>

namespace pcskeleton {

namespace {
// Only distances are computed: no exact predicates needed.
using Kernel = CGAL::Simple_cartesian<double>;
using Point3 = Kernel::Point_3;
using PointMap = CGAL::Pointer_property_map<Point3>::type;
using SearchTraits = CGAL::Search_traits_adapter<std::size_t, PointMap, CGAL::Search_traits_3<Kernel>>;
using NeighbourSearch = CGAL::Orthogonal_k_neighbor_search<SearchTraits>;
using KdTree = NeighbourSearch::Tree;
using Sphere = CGAL::Fuzzy_sphere<SearchTraits>;

Point3 toCgal(const Point& p) { return Point3(p.x(), p.y(), p.z()); }

// Spreads the low 21 bits of v three apart: one axis of a Morton code.
std::uint64_t spreadBits(std::uint64_t v) {
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffULL;
    v = (v | v << 16) & 0x1f0000ff0000ffULL;
    v = (v | v << 8) & 0x100f00f00f00f00fULL;
    v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
    v = (v | v << 2) & 0x1249249249249249ULL;
    return v;
}

// The points' indices along a Z-order curve: points close in space end up close in memory,
// so a query touches a few cache lines instead of one per candidate. Scans often come in
// an order unrelated to space (merged views, shuffled exports): on a randomly ordered
// 1M-point cloud this makes the k-nearest-neighbour queries several times faster.
std::vector<std::size_t> zOrder(const PointList& points) {
    const std::vector<std::pair<std::uint64_t, std::size_t>> coded = sortedZOrderCodes(points);
    std::vector<std::size_t> order(points.size());
    for (std::size_t r = 0; r < order.size(); ++r) order[r] = coded[r].second;
    return order;
}
}  // namespace

std::vector<std::pair<std::uint64_t, std::size_t>> sortedZOrderCodes(const PointList& points) {
    const Eigen::AlignedBox3d box = boundingBox(points);
    const double extent = std::max(box.sizes().maxCoeff(), std::numeric_limits<double>::min());
    const double cells = double((1 << 21) - 1) / extent;
    std::vector<std::pair<std::uint64_t, std::size_t>> coded(points.size());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < long(points.size()); ++i) {
        const Eigen::Vector3d cell = ((points[std::size_t(i)] - box.min()) * cells).cwiseMax(0.0);
        std::uint64_t code = 0;
        for (int axis = 0; axis < 3; ++axis) code |= spreadBits(std::uint64_t(cell[axis])) << axis;
        coded[std::size_t(i)] = {code, std::size_t(i)};
    }
    // (code, index) pairs are distinct: the order is the same on any number of threads.
    parallelSort(coded.begin(), coded.end());
    return coded;
}

struct PointIndex::Tree {
    explicit Tree(const PointList& points)
        : order(zOrder(points)),
          cgalPoints(makePoints(points, order)),
          pointMap(cgalPoints.data()),
          tree(boost::counting_iterator<std::size_t>(0), boost::counting_iterator<std::size_t>(cgalPoints.size()),
               KdTree::Splitter(), SearchTraits(pointMap)) {
        tree.build();  // now, not lazily at the first query: queries may run in parallel
    }
    static std::vector<Point3> makePoints(const PointList& points, const std::vector<std::size_t>& order) {
        std::vector<Point3> result(order.size());
#pragma omp parallel for schedule(static)
        for (long r = 0; r < long(order.size()); ++r) result[std::size_t(r)] = toCgal(points[order[std::size_t(r)]]);
        return result;
    }
    std::vector<std::size_t> order;  // cgalPoints[r] is points[order[r]]
    std::vector<Point3> cgalPoints;
    PointMap pointMap;
    KdTree tree;
};

PointIndex::PointIndex(const PointList& points) : tree_(std::make_unique<Tree>(points)) {}
PointIndex::~PointIndex() = default;

const std::vector<std::size_t>& PointIndex::spatialOrder() const { return tree_->order; }

void PointIndex::withinRadius(const Point& centre, double radius, std::vector<int>& found) const {
    found.clear();
    const Sphere query(toCgal(centre), radius, 0.0, SearchTraits(tree_->pointMap));
    std::vector<std::size_t> hits;
    tree_->tree.search(std::back_inserter(hits), query);
    found.resize(hits.size());
    for (std::size_t h = 0; h < hits.size(); ++h) found[h] = int(tree_->order[hits[h]]);
}

void PointIndex::nearest(const Point& centre, int k, std::vector<int>& found) const {
    nearestRanks(centre, k, found);
    for (int& f : found) f = int(tree_->order[std::size_t(f)]);
}

void PointIndex::nearestRanks(const Point& centre, int k, std::vector<int>& found) const {
    found.clear();
    const NeighbourSearch search(tree_->tree, toCgal(centre), unsigned(k), 0.0, true,
                                 NeighbourSearch::Distance(tree_->pointMap));
    for (const auto& hit : search) found.push_back(int(hit.first));
}

Point PointIndex::pointAtRank(std::size_t rank) const {
    const Point3& p = tree_->cgalPoints[rank];
    return Point(p.x(), p.y(), p.z());
}

}  // namespace pcskeleton
