// Nearest-neighbour and radius queries on a fixed point list (CGAL's k-d tree): the
// k nearest neighbours of the 1-rings, the balls of the thinning's sampling.
#pragma once

#include "pcskeleton/core/point.h"

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace pcskeleton {

// Each point's cell on a Z-order curve through the points' bounding box (21 bits per axis)
// with the point's index, sorted by cell and then index: points close in space come close
// together. The index's order and the normalised cloud's order are both built on it.
std::vector<std::pair<std::uint64_t, std::size_t>> sortedZOrderCodes(const PointList& points);

class PointIndex {
public:
    // `points` must outlive the index and must not change while it exists.
    explicit PointIndex(const PointList& points);
    ~PointIndex();
    PointIndex(const PointIndex&) = delete;
    PointIndex& operator=(const PointIndex&) = delete;

    // Queries are const and safe to run from several threads at once.

    // Replaces `found` with the indices of the points within `radius` of `centre`.
    void withinRadius(const Point& centre, double radius, std::vector<int>& found) const;

    // Replaces `found` with the indices of the `k` points nearest to `centre`, nearest first
    // (a point at `centre` itself included).
    void nearest(const Point& centre, int k, std::vector<int>& found) const;

    // The point indices along a space-filling curve. Queries about many points run several
    // times faster in this order than in a random one: consecutive queries touch the same
    // part of the tree.
    const std::vector<std::size_t>& spatialOrder() const;

    // Work over all points can run in that order throughout, on ranks (places along the
    // curve) instead of indices: the neighbours of a rank are then near it in every array
    // indexed by rank, which on millions of points in a random order is several times
    // faster than following indices around memory.
    // The point at `rank`, that is points[spatialOrder()[rank]].
    Point pointAtRank(std::size_t rank) const;
    // As nearest(), each found point given by its rank.
    void nearestRanks(const Point& centre, int k, std::vector<int>& found) const;

private:
    struct Tree;
    std::unique_ptr<Tree> tree_;
};

}  // namespace pcskeleton
