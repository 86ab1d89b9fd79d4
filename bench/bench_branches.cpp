// Accuracy of the branch measures (skeleton_branches.h) on shapes whose answers are known,
// clean and with 1% noise: limb lengths and angles of a Y and of a five-armed star, the
// radius profile of a tapered tube, how many of a Y's points land in the branch of the
// limb they were sampled from, and a small tree of three orders (the robustness suite's):
// its branch count, total length, volume and orders. The tree's truth is measureBranches
// on its exact curve skeleton (the tube's centre curve), each tip a radius longer (the cap),
// and for the volume, that of the shape itself (its capsules' union).
//
// A limb's true length runs from its junction (or the shape's end) to the end of the shape,
// cap included: what a ruler laid along the object measures. Each true limb is matched to
// the branch whose tip is nearest its end.
//
// Each row is measured on several samples (seeds 1 to N): one sample's figures depend on
// where its points happened to fall, and a method can look right on one and fail on others.
//
// usage: bench_branches [POINTS] [--samples N]      default 6000 points per shape, 10 samples
#include <pcskeleton/core/openmp_wait_policy.h>
#include <pcskeleton/curve_skeleton.h>
#include <pcskeleton/internal/median.h>
#include <pcskeleton/skeleton/skeleton_branches.h>
#include "support/sampled_shapes.h"
#include "support/scan_simulation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

using namespace pcskeleton;

namespace {

struct Limb {
    Point start, end;      // the limb's centre curve, from its junction; the shape ends past `end`
    double angleToParent;  // degrees; NaN for the limb of the root
};

struct Shape {
    std::string name;
    shapes::Polyline curve;
    std::vector<Limb> limbs;
    double radius;
};

constexpr double kRadius = 0.06;

Shape yShape() {
    const Point base(0, 0, 0), fork(0, 0, 1), left(-0.5, 0, 1.5), right(0.6, 0, 1.6);
    return {"Y", {{base, fork}, {fork, left}, {fork, right}},
            {{fork, base, NAN}, {fork, left, 45.0}, {fork, right, 45.0}}, kRadius};
}

Shape star() {
    // Five arms from a centre in the x-z plane, one pointing down (the root's), the others
    // 60, 120, 180 and 240 degrees from it.
    const Point centre(0, 0, 0.8);
    Shape s{"star", {}, {}, kRadius};
    const double lengths[] = {0.8, 0.5, 0.7, 0.6, 0.4};
    for (int arm = 0; arm < 5; ++arm) {
        const double a = M_PI / 3.0 * arm;  // from straight down
        const Point end = centre + lengths[arm] * Point(std::sin(a), 0, -std::cos(a));
        s.curve.push_back({centre, end});
        // Angles are measured from the root arm's direction where it ends (up, at the
        // centre) to each other arm's.
        s.limbs.push_back({centre, end, arm == 0 ? NAN : std::abs(180.0 - 60.0 * arm)});
    }
    return s;
}

// The tip of the branch nearest to `end`, with its branch.
const Branch* nearestBranch(const SkeletonGraph& skeleton, const SkeletonBranches& b, const Point& end) {
    const Branch* best = nullptr;
    double nearest = INFINITY;
    for (const Branch& branch : b.branches) {
        for (int n : {branch.nodes.front(), branch.nodes.back()}) {
            const double d = (skeleton.nodes[std::size_t(n)] - end).norm();
            if (d < nearest) nearest = d, best = &branch;
        }
    }
    return best;
}

struct LimbMeasure {
    double worstLength = 0, worstAngle = 0, pointsRight = 0;  // % of the length, degrees, % of the points
};

LimbMeasure measureLimbs(const Shape& shape, double noise, std::size_t n, std::uint32_t seed) {
    PointList points = shapes::tube(shape.curve, shape.radius, n, seed);
    if (noise > 0) points = shapes::withNoise(points, noise, seed);
    const SkeletonResult result = computeCurveSkeleton(points);
    const SkeletonBranches b = measureBranches(result.skeleton, points);
    double worstLength = 0, worstAngle = 0;
    for (const Limb& limb : shape.limbs) {
        // The shape ends a radius past the curve (the cap).
        const double truth = (limb.end - limb.start).norm() + shape.radius;
        const Branch* branch = nearestBranch(result.skeleton, b, limb.end);
        if (!branch) continue;
        worstLength = std::max(worstLength, std::abs(branch->length - truth) / truth);
        if (!std::isnan(limb.angleToParent) && !std::isnan(branch->angleToParent)) {
            worstAngle = std::max(worstAngle, std::abs(branch->angleToParent - limb.angleToParent));
        }
    }
    // Segmentation: each point's true limb is the segment nearest it.
    std::size_t right = 0, counted = 0;
    std::vector<const Branch*> branchOfLimb;
    for (const Limb& limb : shape.limbs) branchOfLimb.push_back(nearestBranch(result.skeleton, b, limb.end));
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (b.pointBranch[i] < 0) continue;
        std::size_t limb = 0;
        for (std::size_t l = 1; l < shape.curve.size(); ++l) {
            if (shapes::distanceToSegment(points[i], shape.curve[l].a, shape.curve[l].b) <
                shapes::distanceToSegment(points[i], shape.curve[limb].a, shape.curve[limb].b)) {
                limb = l;
            }
        }
        ++counted;
        right += branchOfLimb[limb] == &b.branches[std::size_t(b.pointBranch[i])];
    }
    return {100 * worstLength, worstAngle, counted ? 100.0 * right / double(counted) : 0.0};
}

// A tube along z whose radius falls linearly from 0.15 to 0.05 over a length of 2, sampled
// uniformly by area; the share of nodes (by bone length) whose radius is within 10% of the
// truth at their height, away from the ends (10% of the length at each).
struct TaperMeasure {
    double within = 0, volume = 0, length = 0;  // % of the length; errors in %
};

TaperMeasure measureTaper(double noise, std::size_t n, std::uint32_t seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    const auto radiusAt = [](double z) { return 0.15 - 0.05 * z; };
    PointList points;
    while (points.size() < n) {
        const double z = 2 * unit(random), angle = 2 * M_PI * unit(random);
        if (unit(random) * 0.15 > radiusAt(z)) continue;  // density grows with the radius
        points.emplace_back(radiusAt(z) * std::cos(angle), radiusAt(z) * std::sin(angle), z);
    }
    if (noise > 0) points = shapes::withNoise(points, noise, seed);
    const SkeletonResult result = computeCurveSkeleton(points);
    const SkeletonGraph& s = result.skeleton;
    double within = 0, total = 0;
    for (const Edge& e : s.edges) {
        const double length = (s.nodes[e[0]] - s.nodes[e[1]]).norm();
        for (int node : {e[0], e[1]}) {
            const double z = s.nodes[node].z();
            if (z < 0.2 || z > 1.8) continue;
            total += length / 2;
            within += std::abs(s.radii[node] - radiusAt(z)) <= 0.1 * radiusAt(z) ? length / 2 : 0.0;
        }
    }
    const SkeletonBranches b = measureBranches(s);
    const double volume = M_PI * 2.0 / 3.0 * (0.15 * 0.15 + 0.15 * 0.05 + 0.05 * 0.05);
    double measured = 0, length = 0;
    for (const Branch& branch : b.branches) measured += branch.volume, length += branch.length;
    return {total > 0 ? 100 * within / total : 0.0, 100 * (measured - volume) / volume, 100 * (length - 2.0) / 2.0};
}

// The volume of the union of capsules of radius r around the segments: the tube's shape,
// caps included and overlaps at junctions once. Monte Carlo over its bounding box, 2M
// samples: within 0.3% (one standard error about 0.1%).
double tubeVolume(const shapes::Polyline& curve, double r) {
    Eigen::AlignedBox3d box;
    for (const auto& segment : curve) box.extend(segment.a), box.extend(segment.b);
    box.min().array() -= r;
    box.max().array() += r;
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0, 1);
    const std::size_t samples = 2000000;
    std::size_t inside = 0;
    for (std::size_t i = 0; i < samples; ++i) {
        const Point p = box.min() + Point(unit(random), unit(random), unit(random)).cwiseProduct(box.sizes());
        for (const auto& segment : curve) {
            if (shapes::distanceToSegment(p, segment.a, segment.b) <= r) {
                ++inside;
                break;
            }
        }
    }
    return box.volume() * double(inside) / double(samples);
}

struct TreeMeasure {
    bool branchesExact = false;
    double length = 0, volume = 0;  // errors in %
    int ordersRight = 0, ordersJudged = 0;
    std::vector<double> branchLengths;  // each judged branch's length error, in %
};

TreeMeasure measureTree(double noise, std::size_t n, std::uint32_t seed) {
    const double radius = 0.06;
    // The suite's tree made lopsided (the right side lower and shorter), and each fork's two
    // twigs of clearly different lengths (0.54 and 0.47 on the left, 0.49 and 0.43 on the
    // right), so that no main axis is a tie: where two continuations are about as long, which
    // is the main axis is decided by the noise, and the truth by nothing.
    const Point fork(0, 0, 0.8), left(-0.4, 0, 1.3), right(0.35, 0, 1.2);
    const shapes::Polyline tree{{Point(0, 0, 0), fork},           {fork, left},
                                {fork, right},                    {left, Point(-0.55, 0.25, 1.75)},
                                {left, Point(-0.65, -0.2, 1.65)}, {right, Point(0.5, 0.2, 1.55)},
                                {right, Point(0.65, -0.25, 1.5)}};
    const SkeletonGraph exact = shapes::curveSkeleton(tree, radius);
    const SkeletonBranches truth = measureBranches(exact);
    PointList points = shapes::tube(tree, radius, n, seed);
    if (noise > 0) points = shapes::withNoise(points, noise, seed);
    const SkeletonResult result = computeCurveSkeleton(points);
    const SkeletonBranches b = measureBranches(result.skeleton);
    double trueLength = 0, length = 0, volume = 0;
    const double trueVolume = tubeVolume(tree, radius);
    int ordersRight = 0, ordersJudged = 0;
    std::vector<double> branchLengths;
    const std::vector<int> degree = nodeDegrees(exact.nodeCount(), exact.edges);
    for (const Branch& branch : truth.branches) {
        // Tips and the root end a radius past the curve (the cap).
        trueLength += branch.length + radius * (degree[std::size_t(branch.nodes.back())] == 1);
        if (branch.length < 3 * result.quality.nodeSpacing) continue;
        // The measured branch holding the node nearest to the middle of the true one.
        const Point middle = (exact.nodes[std::size_t(branch.nodes.front())] + exact.nodes[std::size_t(branch.nodes.back())]) / 2;
        std::size_t nearest = 0;
        for (std::size_t m = 1; m < result.skeleton.nodeCount(); ++m) {
            if ((result.skeleton.nodes[m] - middle).norm() < (result.skeleton.nodes[nearest] - middle).norm()) nearest = m;
        }
        const int found = b.nodeBranch[nearest];
        ++ordersJudged;
        ordersRight += found >= 0 && b.branches[std::size_t(found)].order == branch.order;
        if (found >= 0) {
            const bool tip = degree[std::size_t(branch.nodes.back())] == 1, root = branch.parent < 0;
            const double truth = branch.length + radius * (int(tip) + int(root));  // caps
            branchLengths.push_back(100 * (b.branches[std::size_t(found)].length - truth) / truth);
        }
    }
    trueLength += radius;  // the root's cap
    for (const Branch& branch : b.branches) length += branch.length, volume += branch.volume;
    return {b.branches.size() == truth.branches.size(), 100 * (length - trueLength) / trueLength,
            100 * (volume - trueVolume) / trueVolume, ordersRight, ordersJudged, branchLengths};
}

// Curved tubes, held out when the branches' course (fork points, smoothing) was chosen on the
// Y and the star: a helix of two turns (radius 0.5, rising 1) and a trefoil knot (a loop),
// tube radius 0.06, 400 segments each. The measured total length against the curve's (and
// for the helix its two caps), the volume against the tube's, the nodes' median radius
// against the tube's.
struct CurveMeasure {
    double length = 0, bones = 0, volume = 0, radius = 0;  // errors in %
};

CurveMeasure measureCurve(bool knot, double noise, std::size_t n, std::uint32_t seed) {
    shapes::Polyline curve;
    const auto at = [knot](double s) {
        const double u = 2 * M_PI * s;
        return knot ? Point(std::sin(u) + 2 * std::sin(2 * u), std::cos(u) - 2 * std::cos(2 * u), -std::sin(3 * u)) * 0.4
                    : Point(0.5 * std::cos(2 * u), 0.5 * std::sin(2 * u), s);
    };
    double trueLength = knot ? 0.0 : 2 * kRadius;
    for (int i = 0; i < 400; ++i) {
        curve.push_back({at(i / 400.0), at((i + 1) / 400.0)});
        trueLength += (curve.back().b - curve.back().a).norm();
    }
    PointList points = shapes::tube(curve, kRadius, n, seed);
    if (noise > 0) points = shapes::withNoise(points, noise, seed);
    const SkeletonResult result = computeCurveSkeleton(points);
    const SkeletonBranches b = measureBranches(result.skeleton);
    double length = 0, bones = 0, volume = 0;
    for (const Branch& branch : b.branches) length += branch.length, volume += branch.volume;
    for (const Edge& e : result.skeleton.edges) bones += (result.skeleton.nodes[e[0]] - result.skeleton.nodes[e[1]]).norm();
    // The tube's volume: a cylinder along the curve (and for the helix two half-ball caps).
    const double curveLength = trueLength - (knot ? 0.0 : 2 * kRadius);
    const double trueVolume = M_PI * kRadius * kRadius * curveLength + (knot ? 0.0 : 4.0 / 3.0 * M_PI * std::pow(kRadius, 3));
    return {100 * (length - trueLength) / trueLength, 100 * (bones - trueLength) / trueLength,
            100 * (volume - trueVolume) / trueVolume, 100 * (median(result.skeleton.radii) - kRadius) / kRadius};
}

// Median and worst (largest in magnitude, with its sign) of a measure over the samples.
struct Spread {
    double median, worst;
};

Spread spread(std::vector<double> values) {
    Spread result{median(values), 0.0};
    for (double v : values) {
        if (std::abs(v) > std::abs(result.worst)) result.worst = v;
    }
    return result;
}

// A measure on samples 1 to `count` (each its own seed).
template <class Measure>
auto samplesOf(std::uint32_t count, Measure measure) {
    std::vector<decltype(measure(1u))> samples;
    for (std::uint32_t seed = 1; seed <= count; ++seed) samples.push_back(measure(seed));
    return samples;
}

template <class Measure, class Field>
std::vector<double> field(const std::vector<Measure>& samples, Field f) {
    std::vector<double> values;
    for (const Measure& m : samples) values.push_back(f(m));
    return values;
}

template <class Measure, class Test>
int count(const std::vector<Measure>& samples, Test test) {
    return int(std::count_if(samples.begin(), samples.end(), test));
}

}  // namespace

int main(int argc, char** argv) {
    pcskeleton::restartWithPassiveOpenMpWaits(argv);
    std::size_t n = 6000;
    std::uint32_t sampleCount = 10;
    for (int i = 1; i < argc; ++i) {
        if (std::string(argv[i]) == "--samples" && i + 1 < argc) {
            sampleCount = std::uint32_t(std::strtoul(argv[++i], nullptr, 10));
        } else {
            n = std::strtoull(argv[i], nullptr, 10);
        }
    }
    if (n == 0 || sampleCount == 0) {
        std::fprintf(stderr, "usage: bench_branches [POINTS] [--samples N]\n");
        return 2;
    }
    std::printf("Branch measures, %zu points per shape, %u samples per row (seeds 1 to %u): each figure is the\n"
                "median over the samples, then the worst one; \"ok\" counts the samples that meet the target.\n",
                n, sampleCount, sampleCount);
    std::printf("Lengths: the worst limb's error in %% of its length (target 3%%); angles: the worst error in\n"
                "degrees (target 5); points: the share of points in their limb's branch (target 95%% on the Y).\n");
    std::printf("%-6s %-6s %21s %6s %19s %6s %19s\n", "shape", "noise", "length err", "ok", "angle err", "ok",
                "points right");
    for (const Shape& shape : {yShape(), star()}) {
        for (double noise : {0.0, 0.01}) {
            const auto samples = samplesOf(sampleCount, [&](std::uint32_t seed) { return measureLimbs(shape, noise, n, seed); });
            const Spread length = spread(field(samples, [](const LimbMeasure& m) { return m.worstLength; }));
            const Spread angle = spread(field(samples, [](const LimbMeasure& m) { return m.worstAngle; }));
            const std::vector<double> right = field(samples, [](const LimbMeasure& m) { return m.pointsRight; });
            std::printf("%-6s %-6s %9.1f%% (%6.1f%%) %3d/%-2u %8.1f (%6.1f) %3d/%-2u %8.1f%% (%5.1f%%)\n", shape.name.c_str(),
                        noise > 0 ? "1%" : "clean", length.median, length.worst,
                        count(samples, [](const LimbMeasure& m) { return m.worstLength <= 3.0; }), sampleCount,
                        angle.median, angle.worst, count(samples, [](const LimbMeasure& m) { return m.worstAngle <= 5.0; }),
                        sampleCount, median(right), *std::min_element(right.begin(), right.end()));
        }
    }
    for (double noise : {0.0, 0.01}) {
        const auto samples = samplesOf(sampleCount, [&](std::uint32_t seed) { return measureTaper(noise, n, seed); });
        const std::vector<double> within = field(samples, [](const TaperMeasure& m) { return m.within; });
        const Spread volume = spread(field(samples, [](const TaperMeasure& m) { return m.volume; }));
        const Spread length = spread(field(samples, [](const TaperMeasure& m) { return m.length; }));
        std::printf("taper  %-6s radius within 10%% along %.1f%% (lowest %.1f%%) of the length, ok %d/%u (target 90%%); "
                    "volume %+.1f%% (%+.1f%%), length %+.1f%% (%+.1f%%)\n",
                    noise > 0 ? "1%" : "clean", median(within), *std::min_element(within.begin(), within.end()),
                    count(samples, [](const TaperMeasure& m) { return m.within >= 90.0; }), sampleCount, volume.median,
                    volume.worst, length.median, length.worst);
    }
    for (double noise : {0.0, 0.01}) {
        const auto samples = samplesOf(sampleCount, [&](std::uint32_t seed) { return measureTree(noise, n, seed); });
        const Spread length = spread(field(samples, [](const TreeMeasure& m) { return m.length; }));
        const Spread volume = spread(field(samples, [](const TreeMeasure& m) { return m.volume; }));
        int right = 0, judged = 0;
        std::vector<double> branchErrors;
        for (const TreeMeasure& m : samples) {
            right += m.ordersRight, judged += m.ordersJudged;
            for (double e : m.branchLengths) branchErrors.push_back(std::abs(e));
        }
        std::printf("tree   %-6s branch count exact %d/%u; total length %+.1f%% (%+.1f%%) ok %d/%u (target 5%%), "
                    "volume %+.1f%% (%+.1f%%) ok %d/%u (target 15%%); "
                    "orders right %d/%d, all right in %d/%u; each branch's length off by %.1f%% (%.1f%%)\n",
                    noise > 0 ? "1%" : "clean", count(samples, [](const TreeMeasure& m) { return m.branchesExact; }),
                    sampleCount, length.median, length.worst,
                    count(samples, [](const TreeMeasure& m) { return std::abs(m.length) <= 5.0; }), sampleCount,
                    volume.median, volume.worst,
                    count(samples, [](const TreeMeasure& m) { return std::abs(m.volume) <= 15.0; }), sampleCount, right, judged,
                    count(samples, [](const TreeMeasure& m) { return m.ordersRight == m.ordersJudged; }), sampleCount,
                    median(branchErrors), *std::max_element(branchErrors.begin(), branchErrors.end()));
    }
    for (bool knot : {false, true}) {
        for (double noise : {0.0, 0.01}) {
            const auto samples = samplesOf(sampleCount, [&](std::uint32_t seed) { return measureCurve(knot, noise, n, seed); });
            const Spread length = spread(field(samples, [](const CurveMeasure& m) { return m.length; }));
            const Spread bones = spread(field(samples, [](const CurveMeasure& m) { return m.bones; }));
            const Spread volume = spread(field(samples, [](const CurveMeasure& m) { return m.volume; }));
            const Spread radius = spread(field(samples, [](const CurveMeasure& m) { return m.radius; }));
            std::printf("%-7s %-6s total length %+.1f%% (%+.1f%%) (the bones as they lie: %+.1f%% (%+.1f%%)), "
                        "volume %+.1f%% (%+.1f%%), median radius %+.1f%% (%+.1f%%)\n",
                        knot ? "trefoil" : "helix", noise > 0 ? "1%" : "clean", length.median, length.worst, bones.median,
                        bones.worst, volume.median, volume.worst, radius.median, radius.worst);
        }
    }
    return 0;
}
