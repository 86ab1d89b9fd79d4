#include "pcskeleton/reconstruction/topology_control.h"

#include "pcskeleton/internal/disjoint_sets.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <queue>
#include <utility>

namespace pcskeleton {

namespace {

// How far outside a removed inside node is put, in cells: well above the thousandth of a
// cell that extraction pushes off zero, small enough that the surface stays near the node.
constexpr double kJustOutside = 0.1;
// In a cell whose inside or outside corners touch only diagonally, the inside values are
// brought to at most this close to zero and the outside ones to at least kNudgedOutside:
// then every ambiguity test of marching cubes (face saddles, the cell's centre) comes out
// "outside", which connects the outside diagonally and not the inside, as (6, 26) does.
constexpr double kNudgedInside = 0.03;
constexpr double kNudgedOutside = 0.3;

// A node's 3x3x3 neighbourhood: position p = (dx+1) + 3(dy+1) + 9(dz+1), 13 the node itself.
constexpr int kCentre = 13;

// Position masks over the 27 bits of a neighbourhood, for whole-mask moves by one step.
constexpr std::uint32_t kAllPositions = (1u << 27) - 1;

constexpr std::uint32_t positionsWhere(int axis, int coordinate) {
    std::uint32_t mask = 0;
    for (int p = 0; p < 27; ++p) {
        const int c = axis == 0 ? p % 3 : axis == 1 ? p / 3 % 3 : p / 9;
        if (c == coordinate) mask |= 1u << p;
    }
    return mask;
}

constexpr std::array<int, 3> kAxisStride = {1, 3, 9};

// The positions in `m` and their neighbours one step along `axis`, either way.
constexpr std::uint32_t stepAlong(std::uint32_t m, int axis) {
    const int stride = kAxisStride[std::size_t(axis)];
    return m | ((m & ~positionsWhere(axis, 2)) << stride) | ((m & ~positionsWhere(axis, 0)) >> stride);
}

// Face (6-) neighbours: one step along a single axis.
constexpr std::uint32_t faceDilation(std::uint32_t m) {
    return (stepAlong(m, 0) | stepAlong(m, 1) | stepAlong(m, 2)) & kAllPositions;
}

// 26-neighbours: a step along each axis in turn (the 3x3x3 cube is their product).
constexpr std::uint32_t cubeDilation(std::uint32_t m) { return stepAlong(stepAlong(stepAlong(m, 0), 1), 2) & kAllPositions; }

constexpr std::uint32_t positionsWithinTwoFaceSteps() {
    std::uint32_t mask = 0;
    for (int p = 0; p < 27; ++p) {
        const int l1 = std::abs(p % 3 - 1) + std::abs(p / 3 % 3 - 1) + std::abs(p / 9 - 1);
        if (l1 >= 1 && l1 <= 2) mask |= 1u << p;
    }
    return mask;
}
constexpr std::uint32_t kCentreBit = 1u << kCentre;
constexpr std::uint32_t kEighteenNeighbours = positionsWithinTwoFaceSteps();
constexpr std::uint32_t kFaceNeighbours = faceDilation(kCentreBit) & ~kCentreBit;

// Components of `members` (a mask of positions, centre excluded) under `dilate`; with
// `mustTouch`, only those containing one of its positions are counted. Stops counting at 3.
template <std::uint32_t (*dilate)(std::uint32_t)>
int countComponents(std::uint32_t members, std::uint32_t mustTouch) {
    int count = 0;
    while (members && count < 3) {
        std::uint32_t component = members & (~members + 1), grown = 0;
        while (grown != component) {
            grown = component;
            component = dilate(component) & members;
        }
        members &= ~component;
        count += (component & mustTouch) != 0;
    }
    return count;
}

// Around a node of a (6, 26) region: the 6-components of the inside (within its
// 18-neighbourhood) that it touches by a face, and the 26-components of the outside.
struct LocalComponents {
    int inside, outside;
};

LocalComponents localComponents(std::uint32_t inside) {
    const std::uint32_t inside18 = inside & kEighteenNeighbours;
    const std::uint32_t outside26 = ~inside & kAllPositions & ~kCentreBit;
    return {countComponents<faceDilation>(inside18, kFaceNeighbours), countComponents<cubeDilation>(outside26, kAllPositions)};
}

// A simple point: adding or removing it changes no component, tunnel or cavity.
bool isSimple(const LocalComponents& c) { return c.inside == 1 && c.outside == 1; }

// Adding it joins two pieces of the inside that meet nowhere else nearby, and splits no
// outside: within one part of the region, it closes exactly one loop.
bool closesOneLoop(const LocalComponents& c) { return c.inside == 2 && c.outside == 1; }

// localComponents remembered by neighbourhood: a growth meets few distinct ones, and
// counting components by repeated dilation dominated the topology control's time
// (docs/benchmarks.md#measurements-behind-the-constants).
class LocalComponentsCache {
public:
    LocalComponents of(std::uint32_t inside) {
        // Multiplicative hashing of the 26 neighbour bits into a direct-mapped table.
        Entry& entry = table_[(inside * 2654435761u) >> (32 - kTableBits)];
        if (!entry.filled || entry.inside != inside) entry = {inside, true, localComponents(inside)};
        return entry.components;
    }

private:
    static constexpr int kTableBits = 14;
    struct Entry {
        std::uint32_t inside = 0;
        bool filled = false;
        LocalComponents components{};
    };
    std::vector<Entry> table_ = std::vector<Entry>(std::size_t(1) << kTableBits);
};

// Offsets of the 27 positions, (dx, dy, dz) each in -1..1.
constexpr std::array<int, 3> offsetOf(int p) { return {p % 3 - 1, p / 3 % 3 - 1, p / 9 - 1}; }

class Region {
public:
    explicit Region(const FieldGrid& grid) : grid_(grid), member_(grid.size(), 0) {
        for (int p = 0; p < 27; ++p) {
            const std::array<int, 3> d = offsetOf(p);
            stride_[p] = d[0] + std::ptrdiff_t(grid.nodes[0]) * (d[1] + std::ptrdiff_t(grid.nodes[1]) * d[2]);
        }
    }
    bool contains(std::size_t n) const { return member_[n] != 0; }
    void add(std::size_t n) { member_[n] = 1; }
    std::size_t neighbour(std::size_t n, int p) const { return std::size_t(std::ptrdiff_t(n) + stride_[p]); }
    // The region's components around node n, without n.
    LocalComponents componentsAround(std::size_t n) {
        std::uint32_t mask = 0;
        for (int p = 0; p < 27; ++p)
            if (p != kCentre && member_[neighbour(n, p)]) mask |= 1u << p;
        return components_.of(mask);
    }
    bool interior(std::size_t n) const {
        const auto [i, j, k] = grid_.coordinates(n);
        return !grid_.isBoundary(i, j, k);
    }

private:
    const FieldGrid& grid_;
    std::vector<std::uint8_t> member_;
    std::array<std::ptrdiff_t, 27> stride_{};
    LocalComponentsCache components_;
};

// The skeleton drawn into the region as 6-connected chains of grid nodes, with its own
// topology. The bones of a spanning forest are drawn node by node taking simple points
// only: a chain that zig-zags within a cell or passes a cell from another bone must not
// close a loop the skeleton has not. A chain blocked on the way (its next cell would join
// another chain, where two bones pass close) leaves its end for another bone to reach;
// otherwise everything beyond it, and the cycles through it, would be lost. Each remaining
// bone closes one of the skeleton's cycles: it is drawn by simple points too, plus the one
// cell where it meets the region again and closes its loop; cells that would close more
// are left out. Kept off the grid's boundary.
struct DrawnSkeleton {
    std::vector<std::size_t> seeds;  // the grid nodes taken
    std::vector<Edge> openBones;     // cycle-closing bones whose loop could not be closed
};

DrawnSkeleton drawSkeleton(const FieldGrid& grid, const SkeletonGraph& skeleton, Region& region) {
    DrawnSkeleton result;
    std::vector<std::size_t>& seeds = result.seeds;
    const auto cellOf = [&](const Point& p) {
        std::array<int, 3> c{};
        for (int a = 0; a < 3; ++a)
            c[a] = std::clamp(int(std::lround((p[a] - grid.origin[a]) / grid.spacing)), 1, grid.nodes[a] - 2);
        return c;
    };
    const auto add = [&](std::size_t n) {
        region.add(n);
        seeds.push_back(n);
    };
    // A bone's chain, one axis at a time from a to b, so that consecutive nodes share a face.
    // A cycle-closing bone may take one node that closes a loop.
    const auto drawBone = [&](const Point& a, const Point& b, bool closesCycle) {
        bool loopClosed = false;
        const int steps = std::max(1, int(std::ceil(4 * (b - a).norm() / grid.spacing)));
        std::array<int, 3> at = cellOf(a);
        for (int s = 1; s <= steps; ++s) {
            const std::array<int, 3> next = cellOf(a + (b - a) * (double(s) / steps));
            while (at != next) {
                int axis = 0;
                for (int c = 1; c < 3; ++c)
                    if (std::abs(next[c] - at[c]) > std::abs(next[axis] - at[axis])) axis = c;
                at[axis] += next[axis] > at[axis] ? 1 : -1;
                const std::size_t n = grid.index(at[0], at[1], at[2]);
                if (region.contains(n)) continue;
                const LocalComponents around = region.componentsAround(n);
                if (isSimple(around)) {
                    add(n);
                } else if (closesCycle && !loopClosed && closesOneLoop(around)) {
                    add(n);
                    loopClosed = true;
                }
            }
        }
        return loopClosed;
    };
    const auto nodeCell = [&](std::size_t node) {
        const std::array<int, 3> c = cellOf(skeleton.nodes[node]);
        return grid.index(c[0], c[1], c[2]);
    };
    const auto drawn = [&](int node) { return region.contains(nodeCell(std::size_t(node))); };
    // Spanning forest, breadth first from each component's first node: a bone is drawn
    // from a node already drawn, so its chain starts in the region.
    const std::vector<std::vector<int>> neighbours = adjacencyLists(skeleton.nodeCount(), skeleton.edges);
    std::vector<int> parent(skeleton.nodeCount(), -2);  // -2 not reached, -1 a root
    // One root per component of the skeleton: a node no bone could reach is not a new part.
    DisjointSets parts(skeleton.nodeCount());
    for (const Edge& e : skeleton.edges) parts.unite(e[0], e[1]);
    std::vector<char> partStarted(skeleton.nodeCount(), 0);
    for (std::size_t root = 0; root < skeleton.nodeCount(); ++root) {
        char& started = partStarted[std::size_t(parts.find(int(root)))];
        if (started) continue;
        started = 1;
        parent[root] = -1;
        if (!region.contains(nodeCell(root))) add(nodeCell(root));  // a new component
        std::vector<int> queue{int(root)};
        for (std::size_t q = 0; q < queue.size(); ++q) {
            const int from = queue[q];
            for (int to : neighbours[from]) {
                if (parent[to] != -2) continue;
                drawBone(skeleton.nodes[from], skeleton.nodes[to], false);
                if (!drawn(to)) continue;  // blocked: left for another bone
                parent[to] = from;
                queue.push_back(to);
            }
        }
    }
    // The other bones, between ends the forest reached (a chain from an end left out would
    // start a part of its own; the cycle is then missing and the caller's check says so).
    for (const Edge& e : skeleton.edges) {
        if (parent[e[0]] == e[1] || parent[e[1]] == e[0] || !drawn(e[0]) || !drawn(e[1])) continue;
        // From the other end if a crowded cell blocked the way.
        if (!drawBone(skeleton.nodes[e[0]], skeleton.nodes[e[1]], true) &&
            !drawBone(skeleton.nodes[e[1]], skeleton.nodes[e[0]], true))
            result.openBones.push_back(e);
    }
    return result;
}

// Grows the region from the seeds (already in it) through the nodes with negative values,
// most negative first, taking simple points only. A node refused now is looked at again whenever one of
// its neighbours joins.
void grow(Region& region, const std::vector<double>& values, const std::vector<std::size_t>& seeds) {
    using Entry = std::pair<double, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> candidates;
    // A node waits in the queue once: a second entry, with the same key, would be taken
    // right after the first, with nothing changed in between.
    std::vector<std::uint8_t> waiting(values.size(), 0);
    const auto offerNeighbours = [&](std::size_t n) {
        for (int p = 0; p < 27; ++p) {
            const std::size_t m = region.neighbour(n, p);
            if (p != kCentre && values[m] < 0 && !waiting[m] && !region.contains(m) && region.interior(m)) {
                waiting[m] = 1;
                candidates.push({values[m], m});
            }
        }
    };
    for (std::size_t s : seeds) offerNeighbours(s);
    while (!candidates.empty()) {
        const std::size_t n = candidates.top().second;
        candidates.pop();
        waiting[n] = 0;
        if (region.contains(n) || !isSimple(region.componentsAround(n))) continue;
        region.add(n);
        offerNeighbours(n);
    }
}

// Corners of a cell (bits of `corners`) in groups joined along the cell's edges.
int edgeComponents(unsigned corners) {
    int components = 0;
    while (corners) {
        unsigned component = corners & (~corners + 1), grown = 0;
        while (grown != component) {
            grown = component;
            for (int c = 0; c < 8; ++c)
                if ((component >> c) & 1u)
                    for (int bit = 0; bit < 3; ++bit) component |= (1u << (c ^ (1 << bit))) & corners;
        }
        corners &= ~component;
        ++components;
    }
    return components;
}

// Where two inside (or two outside) corners of a cell touch only along a face diagonal or
// through the cell's centre, marching cubes decides from the values whether they connect.
// The region is 6-connected and the outside 26-connected: make the outside values dominate
// there, signs unchanged.
void separateDiagonalContacts(const FieldGrid& grid, std::vector<double>& values) {
    const double inside = -kNudgedInside * grid.spacing, outside = kNudgedOutside * grid.spacing;
    // Corner c of a cell is at (c & 1, c >> 1 & 1, c >> 2); two corners share a cell edge
    // when they differ in one bit.
    for (int k = 0; k + 1 < grid.nodes[2]; ++k)
        for (int j = 0; j + 1 < grid.nodes[1]; ++j)
            for (int i = 0; i + 1 < grid.nodes[0]; ++i) {
                std::array<std::size_t, 8> corner{};
                unsigned in = 0;
                for (int c = 0; c < 8; ++c) {
                    corner[c] = grid.index(i + (c & 1), j + (c >> 1 & 1), k + (c >> 2));
                    if (values[corner[c]] < 0) in |= 1u << c;
                }
                if (in == 0 || in == 0xFF) continue;
                if (edgeComponents(in) < 2 && edgeComponents(~in & 0xFFu) < 2) continue;  // no ambiguity
                for (int c = 0; c < 8; ++c) {
                    double& v = values[corner[c]];
                    v = v < 0 ? std::max(v, inside) : std::max(v, outside);
                }
            }
}

// A loop of the skeleton that its bone could not close (the chain met the region only
// where it would have closed more than one): once the region has grown, the inside nodes
// left out within the bone's reach are where the data closes it. The most inside of those
// that closes exactly one loop is taken, and growth resumes from it. Returns whether it closed.
bool closeLoopNear(const FieldGrid& grid, const SkeletonGraph& skeleton, const Edge& bone, Region& region,
                   const std::vector<double>& values) {
    const Point a = skeleton.nodes[std::size_t(bone[0])], b = skeleton.nodes[std::size_t(bone[1])];
    const double reach = std::max(skeleton.radii[std::size_t(bone[0])], skeleton.radii[std::size_t(bone[1])]) + grid.spacing;
    std::array<int, 3> low{}, high{};
    for (int axis = 0; axis < 3; ++axis) {
        low[axis] = std::max(1, int(std::floor((std::min(a[axis], b[axis]) - reach - grid.origin[axis]) / grid.spacing)));
        high[axis] = std::min(grid.nodes[axis] - 2, int(std::ceil((std::max(a[axis], b[axis]) + reach - grid.origin[axis]) / grid.spacing)));
    }
    std::size_t best = 0;
    double bestValue = 0.0;
    for (int k = low[2]; k <= high[2]; ++k)
        for (int j = low[1]; j <= high[1]; ++j)
            for (int i = low[0]; i <= high[0]; ++i) {
                const std::size_t n = grid.index(i, j, k);
                if (values[n] >= bestValue || region.contains(n)) continue;
                const Point p = grid.position(i, j, k);
                const double t = std::clamp((p - a).dot(b - a) / std::max((b - a).squaredNorm(), 1e-300), 0.0, 1.0);
                if ((p - (a + t * (b - a))).norm() > reach || !closesOneLoop(region.componentsAround(n))) continue;
                best = n;
                bestValue = values[n];
            }
    if (bestValue >= 0.0) return false;
    region.add(best);
    grow(region, values, {best});
    return true;
}

}  // namespace

TopologyControl constrainToSkeletonTopology(const FieldGrid& grid, const SkeletonGraph& skeleton,
                                            std::vector<double>& values) {
    TopologyControl result;
    Region region(grid);
    const DrawnSkeleton drawing = drawSkeleton(grid, skeleton, region);
    const std::vector<std::size_t>& seeds = drawing.seeds;
    result.seedNodes = seeds.size();
    // The skeleton is inside by definition, even where a bone is thinner than a cell.
    for (std::size_t s : seeds) values[s] = std::min(values[s], -kNudgedInside * grid.spacing);
    grow(region, values, seeds);
    for (const Edge& bone : drawing.openBones) closeLoopNear(grid, skeleton, bone, region, values);

    std::vector<std::size_t> removed;
    for (std::size_t n = 0; n < values.size(); ++n) {
        if (values[n] >= 0) continue;
        ++result.insideNodes;
        if (region.contains(n)) continue;
        values[n] = kJustOutside * grid.spacing;
        removed.push_back(n);
    }
    result.removedNodes = removed.size();

    // The largest 26-connected group of removed nodes: where the data and the skeleton disagree most.
    std::vector<std::uint8_t> isRemoved(values.size(), 0), seen(values.size(), 0);
    for (std::size_t n : removed) isRemoved[n] = 1;
    for (std::size_t start : removed) {
        if (seen[start]) continue;
        std::vector<std::size_t> group{start};
        seen[start] = 1;
        Point sum = Point::Zero();
        for (std::size_t g = 0; g < group.size(); ++g) {
            const std::size_t n = group[g];
            const auto [i, j, k] = grid.coordinates(n);
            sum += grid.position(i, j, k);
            // Removed nodes had negative values, so none is on the boundary: all 26 neighbours exist.
            for (int p = 0; p < 27; ++p) {
                const std::size_t m = region.neighbour(n, p);
                if (p != kCentre && isRemoved[m] && !seen[m]) {
                    seen[m] = 1;
                    group.push_back(m);
                }
            }
        }
        if (group.size() > result.largestRemoval) {
            result.largestRemoval = group.size();
            result.largestRemovalCentre = sum / double(group.size());
        }
    }
    separateDiagonalContacts(grid, values);
    return result;
}

}  // namespace pcskeleton
