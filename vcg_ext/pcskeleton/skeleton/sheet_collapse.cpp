#include "pcskeleton/skeleton/sheet_collapse.h"

#include "pcskeleton/internal/local_plane.h"
#include "pcskeleton/internal/median.h"
#include "pcskeleton/internal/spatial_index.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <vector>

namespace pcskeleton {

namespace {

// The constants were chosen on the tuning half of the robustness suite (its plate with two
// holes, ribbon leaf and tube shapes); docs/benchmarks.md has the measurements.

// Flatness is judged over this many thinning radii: wide enough that noise and sampling do
// not hide a plane, narrow enough that a thick tube's wall is not taken for one.
constexpr double kNeighbourhoodRadii = 2.0;
constexpr std::size_t kFewestNeighbours = 10;
// A sheet's neighbourhood: its second spread at least kSpread of its first (a line's is not),
// its thickness at most kFlat of its second spread (a blob's is not).
constexpr double kSpread = 0.2;
constexpr double kFlat = 0.1;
// The points of one patch face within this angle of its first point's plane.
constexpr double kFacingDegrees = 30.0;
constexpr std::size_t kFewestPatchPoints = 50;
// Narrower patches are leaves and blades that contraction already draws into a line.
constexpr double kWidePatchRadii = 4.0;
// Contraction left a patch alone when its second spread stayed at least this share of what
// it was (a tube's strip narrows towards the axis).
constexpr double kKeptSpread = 0.6;
// A patch with another sheet facing it across its plane on more than this share of its
// points is a face of a thick closed plate, which contraction handles.
constexpr double kLayeredShare = 0.2;
constexpr std::size_t kLayerProbeStride = 7;  // every seventh point is probed
constexpr double kParallelSheets = 0.85;      // |cos| of the angle between their planes
// A patch is a flat stretch of a curved sheet, not a plate, when more than this share of the
// points next to it are sheet points too, facing another way. Plates measure far below it,
// the flat middle of a cupped leaf far above (docs/benchmarks.md, "The order of the input").
constexpr double kCurvingOnShare = 0.5;
// Points next to a patch within this many thinning radii of its plane join it, or within
// kBandDeviations standard deviations of its points' scatter off the plane where that is
// wider: on a noisy plate, the points that noise took too far off for the sheet test. Four
// deviations of a normal distribution leave out about one point in 16000.
constexpr double kBandRadii = 0.5;
constexpr double kBandDeviations = 4.0;
// The grid's cell, in thinning radii. The grid is closed with a disc of kClosingRadii
// thinning radii, or of kGapSpacings point spacings where that is wider: a hole survives
// when such a disc fits in it, and narrower gaps are filled. A plate seen at a grazing angle
// comes back in bands, one per row of the scanner's pixels, with empty bands between them;
// a disc of one thinning radius left parts of those open, as false holes between the bands
// (docs/benchmarks.md, "Scan lines across a plate").
// Spurs shorter than kSpurRadii are cut off. The point spacing is the one that all but a
// tenth of the points have to their nearest: on an unevenly dense scan, the sparse part's
// (whose gaps a median spacing leaves open as false holes).
constexpr double kCellRadii = 0.5;
constexpr double kClosingRadii = 1.5;
constexpr double kGapSpacings = 2.5;
constexpr double kGapQuantile = 0.9;
// Bounds on the grid's work where the node spacing is tiny against the patch or against its
// point spacing (a user's setting on millions of points): coarser cells instead.
constexpr double kLargestGridSide = 4096;
constexpr double kMostClosingCells = 16;
constexpr double kSpurRadii = 2.0;

struct Neighbourhoods {
    std::vector<char> sheet;        // per point
    std::vector<Point> normal;      // per point
    std::vector<double> thickness;  // per point: its neighbourhood's first spread over its second
};

// `points` holds at least kFewestPatchPoints (collapseSheets returns earlier), so the nearest
// kFewestNeighbours always exist.
static_assert(kFewestPatchPoints >= kFewestNeighbours);
Neighbourhoods sheetNeighbourhoods(const PointList& points, const PointIndex& index, double radius) {
    Neighbourhoods n{std::vector<char>(points.size(), 0), std::vector<Point>(points.size(), Point::Zero()),
                     std::vector<double>(points.size(), 0.0)};
    const std::vector<std::size_t>& order = index.spatialOrder();  // consecutive queries share the tree's nodes
#pragma omp parallel
    {
        std::vector<int> found;
#pragma omp for schedule(static)
        for (long rank = 0; rank < long(points.size()); ++rank) {
            const std::size_t i = order[std::size_t(rank)];
            index.withinRadius(points[i], kNeighbourhoodRadii * radius, found);
            // A sparse cloud's ball may hold too few points to show a plane: then the nearest
            // that many, a neighbourhood as wide as the sampling needs.
            if (found.size() < kFewestNeighbours) index.nearest(points[i], int(kFewestNeighbours), found);
            const LocalPlane plane = fitLocalPlane(points, found);
            const Eigen::Vector3d& v = plane.variances;
            n.sheet[i] = v(1) >= kSpread * v(2) && v(0) <= kFlat * v(1);
            n.normal[i] = plane.axes.col(0);
            n.thickness[i] = v(1) > 0 ? v(0) / v(1) : 0.0;
        }
    }
    return n;
}

// Adds to `members` every point reached from them through 1-rings, transitively, that
// `joins` accepts (it marks what it accepts, so that no point is added twice).
template <typename Joins>
void growAlongRings(const OneRings& rings, std::vector<int>& members, const Joins& joins) {
    for (std::size_t k = 0; k < members.size(); ++k) {
        const std::size_t i = std::size_t(members[k]);
        for (const int* j = rings.ringBegin(i); j != rings.ringEnd(i); ++j) {
            if (joins(std::size_t(*j))) members.push_back(*j);
        }
    }
}

// Sheet points joined by 1-rings, each facing within kFacingDegrees of its patch's first
// point. The flattest points seed patches first: their planes are the surest.
std::vector<std::vector<int>> flatPatches(const Neighbourhoods& n, const OneRings& rings) {
    const double facing = std::cos(kFacingDegrees * M_PI / 180.0);
    std::vector<int> seeds;
    for (std::size_t i = 0; i < n.sheet.size(); ++i) {
        if (n.sheet[i]) seeds.push_back(int(i));
    }
    // Equally flat points (an exact plane's) by index: the pipeline's points come in an
    // order their positions fix (point_cloud_input.h).
    std::stable_sort(seeds.begin(), seeds.end(),
                     [&](int a, int b) { return n.thickness[std::size_t(a)] < n.thickness[std::size_t(b)]; });
    std::vector<char> assigned(n.sheet.size(), 0);
    std::vector<std::vector<int>> patches;
    for (const int seed : seeds) {
        if (assigned[std::size_t(seed)]) continue;
        std::vector<int> patch{seed};
        assigned[std::size_t(seed)] = 1;
        const Point& seedNormal = n.normal[std::size_t(seed)];
        growAlongRings(rings, patch, [&](std::size_t m) {
            if (!n.sheet[m] || assigned[m] || std::abs(n.normal[m].dot(seedNormal)) < facing) return false;
            assigned[m] = 1;
            return true;
        });
        if (patch.size() >= kFewestPatchPoints) patches.push_back(std::move(patch));
    }
    return patches;
}

// A plate ends at its rim, at its holes or at a crease, where the points next to it are no
// sheet points or none at all; a flat stretch of a curved sheet (a cupped leaf) goes on into
// sheet points that face another way.
bool endsAtItsRim(const Neighbourhoods& n, const OneRings& rings, const std::vector<int>& patch) {
    std::vector<char> member(n.sheet.size(), 0);
    for (int i : patch) member[std::size_t(i)] = 1;
    std::size_t onSheets = 0, beside = 0;
    for (int i : patch) {
        for (const int* j = rings.ringBegin(std::size_t(i)); j != rings.ringEnd(std::size_t(i)); ++j) {
            if (member[std::size_t(*j)]) continue;
            ++beside;
            onSheets += n.sheet[std::size_t(*j)];
        }
    }
    return double(onSheets) <= kCurvingOnShare * double(beside);
}

// Wide, left as wide and flat by contraction, and one layer (the header's step 2).
bool isOneLayerPlate(const PointList& original, const PointList& contracted, const PointIndex& index,
                     const Neighbourhoods& n, const std::vector<int>& patch, const LocalPlane& plane, double radius) {
    if (std::sqrt(plane.variances(1)) < kWidePatchRadii * radius) return false;
    const LocalPlane after = fitLocalPlane(contracted, patch);
    if (after.variances(1) < kKeptSpread * plane.variances(1) || after.variances(0) > kFlat * after.variances(1)) {
        return false;
    }
    // Another sheet across the plane: a point farther off the plane than the thinning radius
    // and than it is along it, whose own plane is parallel (a plate meeting this one at a
    // crease is not).
    const Point normal = plane.axes.col(0);
    const double reach = std::sqrt(plane.variances(2));
    std::size_t probed = 0, layered = 0;
    std::vector<int> around;
    for (std::size_t k = 0; k < patch.size(); k += kLayerProbeStride) {
        const Point& p = original[std::size_t(patch[k])];
        index.withinRadius(p, reach, around);
        ++probed;
        layered += std::any_of(around.begin(), around.end(), [&](int j) {
            const Point d = original[std::size_t(j)] - p;
            const double off = std::abs(d.dot(normal));
            return off > radius && (d - d.dot(normal) * normal).norm() < off &&
                   std::abs(n.normal[std::size_t(j)].dot(normal)) > kParallelSheets;
        });
    }
    return double(layered) <= kLayeredShare * double(probed);
}

// Adds to each patch the points next to it (through 1-rings, transitively) that belong to no
// patch and lie within its band: kBandRadii of its plane, or kBandDeviations of its points'
// scatter off it where that is wider. A point next to two patches (the band along a crease
// where two plates meet) joins the one whose plane it is nearer, whichever patch comes first.
void addBands(const PointList& original, const OneRings& rings,
              const std::vector<LocalPlane>& planes, double radius, std::vector<std::vector<int>>& patches) {
    const std::size_t none = patches.size();
    std::vector<std::size_t> owner(original.size(), none);
    std::vector<double> offset(original.size(), INFINITY);
    std::vector<char> reached(original.size());
    std::vector<char> inPlate(original.size(), 0);
    for (const std::vector<int>& patch : patches) {
        for (int i : patch) inPlate[std::size_t(i)] = 1;
    }
    for (std::size_t p = 0; p < patches.size(); ++p) {
        std::fill(reached.begin(), reached.end(), 0);
        for (int i : patches[p]) reached[std::size_t(i)] = 1;
        std::vector<int> band = patches[p];
        const LocalPlane& plane = planes[p];
        const double halfWidth = std::max(kBandRadii * radius, kBandDeviations * std::sqrt(plane.variances(0)));
        growAlongRings(rings, band, [&](std::size_t m) {
            if (reached[m] || inPlate[m]) return false;
            const double off = std::abs((original[m] - plane.centroid).dot(plane.axes.col(0)));
            if (off > halfWidth) return false;
            reached[m] = 1;
            if (off < offset[m]) offset[m] = off, owner[m] = p;
            return true;
        });
    }
    for (std::size_t m = 0; m < original.size(); ++m) {
        if (owner[m] != none) patches[owner[m]].push_back(int(m));
    }
}

// A binary image; cells outside it read as empty.
struct Grid {
    int width = 0, height = 0;
    std::vector<std::uint8_t> cells;

    Grid(int w, int h) : width(w), height(h), cells(std::size_t(w) * std::size_t(h), 0) {}
    std::size_t at(int x, int y) const { return std::size_t(y) * std::size_t(width) + std::size_t(x); }
    int x(std::size_t cell) const { return int(cell % std::size_t(width)); }
    int y(std::size_t cell) const { return int(cell / std::size_t(width)); }
    bool set(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height && cells[at(x, y)]; }
    int neighbourCount(int x, int y) const {
        int count = 0;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) count += (dx || dy) && set(x + dx, y + dy);
        return count;
    }
};

// Dilation (every cell within `r` cells of a set one) or erosion (every cell whose disc of
// `r` cells is all set).
Grid morphology(const Grid& g, int r, bool erode) {
    Grid out(g.width, g.height);
    for (int y = 0; y < g.height; ++y) {
        for (int x = 0; x < g.width; ++x) {
            bool any = false, all = true;
            for (int dy = -r; dy <= r; ++dy) {
                for (int dx = -r; dx <= r; ++dx) {
                    if (dx * dx + dy * dy > r * r) continue;
                    const bool s = g.set(x + dx, y + dy);
                    any = any || s;
                    all = all && s;
                }
            }
            out.cells[out.at(x, y)] = erode ? all : any;
        }
    }
    return out;
}

// Zhang and Suen's thinning ("A fast parallel algorithm for thinning digital patterns",
// CACM 1984): border cells whose removal keeps the 8-connected shape and its holes go, in
// two alternating passes, until none is left.
void thinToAxis(Grid& g) {
    // The 8 neighbours clockwise from north.
    static constexpr int dx[8] = {0, 1, 1, 1, 0, -1, -1, -1}, dy[8] = {-1, -1, 0, 1, 1, 1, 0, -1};
    std::vector<std::size_t> removed;
    for (bool changed = true; changed;) {
        changed = false;
        for (int pass = 0; pass < 2; ++pass) {
            removed.clear();
            for (int y = 0; y < g.height; ++y) {
                for (int x = 0; x < g.width; ++x) {
                    if (!g.set(x, y)) continue;
                    std::array<bool, 8> p;
                    int count = 0, rises = 0;
                    for (int k = 0; k < 8; ++k) count += p[std::size_t(k)] = g.set(x + dx[k], y + dy[k]);
                    for (std::size_t k = 0; k < 8; ++k) rises += !p[k] && p[(k + 1) % 8];
                    if (count < 2 || count > 6 || rises != 1) continue;
                    const bool north = p[0], east = p[2], south = p[4], west = p[6];
                    const bool removable = pass == 0 ? !(north && east && south) && !(east && south && west)
                                                     : !(north && east && west) && !(north && south && west);
                    if (removable) removed.push_back(g.at(x, y));
                }
            }
            for (std::size_t c : removed) g.cells[c] = 0;
            changed = changed || !removed.empty();
        }
    }
}

// Takes the end cells off `rounds` times: the spurs a ragged rim gives the axis.
void pruneSpurs(Grid& g, int rounds) {
    std::vector<std::size_t> ends;
    for (int round = 0; round < rounds; ++round) {
        ends.clear();
        for (int y = 0; y < g.height; ++y)
            for (int x = 0; x < g.width; ++x)
                if (g.set(x, y) && g.neighbourCount(x, y) == 1) ends.push_back(g.at(x, y));
        if (ends.empty()) return;
        for (std::size_t c : ends) g.cells[c] = 0;
    }
}

// Breadth first from the cells `queue` holds into the set cells of `shape` (8-connected):
// `reach(from, to)` is called once for each cell reached, `from` the cell it was reached from.
// `visited` marks the cells already reached (the sources too).
template <typename Reach>
void spreadOverShape(const Grid& shape, std::deque<std::size_t> queue, std::vector<char>& visited, const Reach& reach) {
    while (!queue.empty()) {
        const std::size_t c = queue.front();
        queue.pop_front();
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                const int x = shape.x(c) + dx, y = shape.y(c) + dy;
                if (!shape.set(x, y) || visited[shape.at(x, y)]) continue;
                visited[shape.at(x, y)] = 1;
                reach(c, shape.at(x, y));
                queue.push_back(shape.at(x, y));
            }
        }
    }
}

// The cell of the shape farthest (in steps between neighbours) from every empty cell: the
// medial axis of a round shape, which the thinning can wear away to nothing.
std::size_t deepestCell(const Grid& shape) {
    std::vector<int> depth(shape.cells.size(), 0);
    std::vector<char> visited(shape.cells.size(), 0);
    std::deque<std::size_t> empty;
    for (std::size_t c = 0; c < shape.cells.size(); ++c) {
        if (!shape.cells[c]) visited[c] = 1, empty.push_back(c);
    }
    std::size_t deepest = 0;
    spreadOverShape(shape, std::move(empty), visited, [&](std::size_t from, std::size_t to) {
        depth[to] = depth[from] + 1;
        if (depth[to] > depth[deepest]) deepest = to;
    });
    return deepest;
}

// Moves the patch's points onto its medial axis (the header's steps 3 and 4).
void moveOntoAxis(const PointList& original, const PointIndex& index, const std::vector<int>& patch,
                  const LocalPlane& plane, double radius, PointList& contracted) {
    const Point u = plane.axes.col(2), v = plane.axes.col(1), normal = plane.axes.col(0);
    double minU = INFINITY, maxU = -INFINITY, minV = INFINITY, maxV = -INFINITY;
    std::vector<double> spacing;
    std::vector<int> found;
    for (int i : patch) {
        const Point d = original[std::size_t(i)] - plane.centroid;
        minU = std::min(minU, d.dot(u)), maxU = std::max(maxU, d.dot(u));
        minV = std::min(minV, d.dot(v)), maxV = std::max(maxV, d.dot(v));
        index.nearest(original[std::size_t(i)], 2, found);
        if (found.size() == 2) spacing.push_back((original[std::size_t(found[1])] - original[std::size_t(i)]).norm());
    }
    const double gap = spacing.empty() ? radius : quantile(spacing, kGapQuantile);
    const double cell = std::max({kCellRadii * radius, std::max(maxU - minU, maxV - minV) / kLargestGridSide,
                                  kGapSpacings * gap / kMostClosingCells});
    const int close = std::max(
        {1, int(std::ceil(kGapSpacings * gap / cell)), int(std::ceil(kClosingRadii * radius / cell - 1e-9))});
    const int margin = close + 2;
    Grid occupied(int((maxU - minU) / cell) + 1 + 2 * margin, int((maxV - minV) / cell) + 1 + 2 * margin);
    std::vector<std::size_t> cellOf;
    for (int i : patch) {
        const Point d = original[std::size_t(i)] - plane.centroid;
        cellOf.push_back(occupied.at(margin + int((d.dot(u) - minU) / cell), margin + int((d.dot(v) - minV) / cell)));
        occupied.cells[cellOf.back()] = 1;
    }
    Grid shape = morphology(morphology(occupied, close, false), close, true);
    for (std::size_t c : cellOf) shape.cells[c] = 1;  // erosion at the rim must not drop a point's own cell
    Grid axis = shape;
    thinToAxis(axis);
    pruneSpurs(axis, int(std::lround(kSpurRadii / kCellRadii)));
    if (std::find(axis.cells.begin(), axis.cells.end(), 1) == axis.cells.end()) axis.cells[deepestCell(shape)] = 1;

    // Each cell of the shape takes the axis cell nearest it across the shape (breadth first,
    // 8-connected): a point never jumps across a hole.
    std::vector<int> nearestAxisCell(axis.cells.size(), -1);
    std::vector<char> visited(axis.cells.size(), 0);
    std::deque<std::size_t> axisCells;
    for (std::size_t c = 0; c < axis.cells.size(); ++c) {
        if (axis.cells[c]) nearestAxisCell[c] = int(c), visited[c] = 1, axisCells.push_back(c);
    }
    spreadOverShape(shape, std::move(axisCells), visited,
                    [&](std::size_t from, std::size_t to) { nearestAxisCell[to] = nearestAxisCell[from]; });
    // A point keeps its place within its cell, shifted by whole cells to the axis cell: moved
    // to the same cell, points stay distinct (the spatial search of thinning cannot split
    // thousands of equal points).
    for (std::size_t k = 0; k < patch.size(); ++k) {
        if (nearestAxisCell[cellOf[k]] < 0) continue;  // a piece of the shape without axis: left as it is
        const auto target = std::size_t(nearestAxisCell[cellOf[k]]);
        const Point d = original[std::size_t(patch[k])] - plane.centroid;
        const double au = d.dot(u) + double(shape.x(target) - shape.x(cellOf[k])) * cell;
        const double av = d.dot(v) + double(shape.y(target) - shape.y(cellOf[k])) * cell;
        contracted[std::size_t(patch[k])] = plane.centroid + au * u + av * v + d.dot(normal) * normal;
    }
}

}  // namespace

SheetCollapseReport collapseSheets(const PointList& original, PointList& contracted, const OneRings& rings,
                                   double radius) {
    SheetCollapseReport report;
    if (original.size() < kFewestPatchPoints || !(radius > 0)) return report;
    const PointIndex index(original);
    const Neighbourhoods n = sheetNeighbourhoods(original, index, radius);
    std::vector<std::vector<int>> plates;
    std::vector<LocalPlane> planes;
    for (std::vector<int>& patch : flatPatches(n, rings)) {
        const LocalPlane plane = fitLocalPlane(original, patch);
        const bool plate =
            endsAtItsRim(n, rings, patch) && isOneLayerPlate(original, contracted, index, n, patch, plane, radius);
        if (!plate) continue;
        plates.push_back(std::move(patch));
        planes.push_back(plane);
    }
    addBands(original, rings, planes, radius, plates);
    for (std::size_t p = 0; p < plates.size(); ++p) {
        moveOntoAxis(original, index, plates[p], planes[p], radius, contracted);
        ++report.patches;
        report.points += plates[p].size();
    }
    return report;
}

}  // namespace pcskeleton
