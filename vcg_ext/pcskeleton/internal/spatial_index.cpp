#include "pcskeleton/internal/spatial_index.h"

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>
#include <boost/iterator/counting_iterator.hpp>

#include <iterator>

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
}  // namespace

struct PointIndex::Tree {
    explicit Tree(const PointList& points)
        : cgalPoints(makePoints(points)),
          pointMap(cgalPoints.data()),
          tree(boost::counting_iterator<std::size_t>(0), boost::counting_iterator<std::size_t>(cgalPoints.size()),
               KdTree::Splitter(), SearchTraits(pointMap)) {
        tree.build();  // now, not lazily at the first query: queries may run in parallel
    }
    static std::vector<Point3> makePoints(const PointList& points) {
        std::vector<Point3> result;
        result.reserve(points.size());
        for (const Point& p : points) result.push_back(toCgal(p));
        return result;
    }
    std::vector<Point3> cgalPoints;
    PointMap pointMap;
    KdTree tree;
};

PointIndex::PointIndex(const PointList& points) : tree_(std::make_unique<Tree>(points)) {}
PointIndex::~PointIndex() = default;

void PointIndex::withinRadius(const Point& centre, double radius, std::vector<int>& found) const {
    found.clear();
    const Sphere query(toCgal(centre), radius, 0.0, SearchTraits(tree_->pointMap));
    std::vector<std::size_t> hits;
    tree_->tree.search(std::back_inserter(hits), query);
    found.assign(hits.begin(), hits.end());
}

void PointIndex::nearest(const Point& centre, int k, std::vector<int>& found) const {
    found.clear();
    const NeighbourSearch search(tree_->tree, toCgal(centre), unsigned(k), 0.0, true,
                                 NeighbourSearch::Distance(tree_->pointMap));
    for (const auto& hit : search) found.push_back(int(hit.first));
}

}  // namespace pcskeleton
