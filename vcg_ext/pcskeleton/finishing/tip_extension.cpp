#include "pcskeleton/finishing/tip_extension.h"

#include "pcskeleton/skeleton/skeleton_structure.h"

#include <algorithm>

namespace pcskeleton {

namespace {

constexpr double kTubeRadii = 1.5;
// The limb ends where the density of its points along the axis falls under this share of
// the density over the tip (see limbEnd): half, where symmetric noise leaves a blurred end.
constexpr double kEndDensityShare = 0.5;
// Fewer points than this in the tube: the farthest one is the end.
constexpr std::size_t kFewestForDensity = 20;

// Where the limb ends along its axis, from the sorted offsets along it of the points of
// its end within its tube. A tube and a round cap have the same density of points along
// their axis (Archimedes' hat-box), so on a clean limb the density stays level up to the
// last point; noise blurs that end into a tail, with points up to two or three deviations
// beyond it, which the farthest point would follow out of the shape. The density over the tip (the
// middle half of its offsets) is compared, from the far end inwards, with the density in
// a window of +-`window` around each point: the first point where it is at least
// kEndDensityShare of the tip's is the end. Noise moves points past the end as often as
// short of it, so the blurred density crosses half its level at the true end; on a clean
// limb that is the last point.
double limbEnd(const std::vector<double>& along, double window) {
    const std::size_t n = along.size();
    if (n < kFewestForDensity || !(window > 0)) return n > 0 ? along.back() : 0.0;
    const double span = along[3 * n / 4] - along[n / 4];
    if (!(span > 0)) return along.back();
    const double tipDensity = double(3 * n / 4 - n / 4) / span;
    for (std::size_t i = n; i-- > n / 2;) {
        const auto from = std::lower_bound(along.begin(), along.end(), along[i] - window);
        const auto to = std::upper_bound(along.begin(), along.end(), along[i] + window);
        if (double(to - from) / (2.0 * window) >= kEndDensityShare * tipDensity) return along[i];
    }
    return along[n / 2];
}

// The tip and the nodes behind it on its limb, up to the first one two node spacings and
// the tip's diameter away (or the limb's other end). The last one sets the limb's direction
// at its tip: on a tube thicker than the node spacing, noise moves the nodes across the
// tube by a share of its radius, which tilts a direction read over less.
std::vector<int> limbEndNodes(const SkeletonGraph& skeleton, const Limb& limb, double nodeSpacing) {
    const Point& tip = skeleton.nodes[limb.path.front()];
    const double back = std::max(2.0 * nodeSpacing, 2.0 * skeleton.radii[limb.path.front()]);
    std::vector<int> nodes;
    for (int n : limb.path) {
        nodes.push_back(n);
        if ((skeleton.nodes[n] - tip).norm() >= back) break;
    }
    return nodes;
}

}  // namespace

TipExtensionReport extendTips(SkeletonGraph& skeleton, const PointList& points, double nodeSpacing,
                              const DataSupport& support) {
    const std::vector<std::vector<int>> pointsOf = pointsOfNodes(skeleton);
    TipExtensionReport report;
    for (const Limb& limb : tipLimbs(skeleton)) {
        const int tip = limb.path.front();
        if (isSpur(skeleton, limb, nodeSpacing) || pointsOf[tip].empty()) continue;
        // The points of the limb's end: the tip's and those of the nodes behind it, up to two
        // node spacings back. Under noise the tip can be a small cluster of the end's
        // straggling points, too few to tell the limb's end from its tail.
        const std::vector<int> endNodes = limbEndNodes(skeleton, limb, nodeSpacing);
        const Point tipPosition = skeleton.nodes[tip];
        const Point direction = (tipPosition - skeleton.nodes[endNodes.back()]).normalized();
        if (!direction.allFinite()) continue;  // coincident nodes: no direction to extend in
        // The limb's thickness is that of its thickest end node: a small tip is thinner.
        double tubeRadius = 0.0;
        for (int n : endNodes) tubeRadius = std::max(tubeRadius, skeleton.radii[n]);
        struct Offset {
            double along, across;  // of a point, relative to the limb's axis through the tip
        };
        std::vector<Offset> offsets;
        for (int n : endNodes) {
            for (int i : pointsOf[n]) {
                const Point offset = points[i] - tipPosition;
                const double along = offset.dot(direction);
                offsets.push_back({along, (offset - along * direction).norm()});
            }
        }

        // Only points within the limb's tube count: an outlier or a noisy point off to the
        // side must not pull the end out.
        std::vector<double> alongTube;
        for (const Offset& o : offsets) {
            if (o.across <= kTubeRadii * tubeRadius) alongTube.push_back(o.along);
        }
        std::sort(alongTube.begin(), alongTube.end());
        const double reach = limbEnd(alongTube, 0.25 * tubeRadius);
        if (reach <= 0.1 * nodeSpacing) continue;

        const double endZone = reach - 0.25 * skeleton.radii[tip];
        double thickness = 0.0;
        int endPoints = 0;
        for (const Offset& o : offsets) {
            if (o.along >= endZone) thickness += o.across, ++endPoints;
        }
        thickness = endPoints > 0 ? thickness / endPoints : 0.0;
        if (!isPositiveFinite(thickness)) thickness = 0.5 * skeleton.radii[tip];

        const Point end = tipPosition + reach * direction;
        const double endRadius = std::min(thickness, skeleton.radii[tip]);
        if (!support.supports(end, endRadius, {})) {
            ++report.refused;
            continue;
        }
        skeleton.nodes.push_back(end);
        skeleton.radii.push_back(endRadius);
        skeleton.edges.push_back({tip, int(skeleton.nodeCount()) - 1});
        ++report.extendedTips;
        report.meanLength += reach;
        report.longest = std::max(report.longest, reach);
    }
    normalizeEdges(skeleton.edges);
    if (report.extendedTips > 0) report.meanLength /= report.extendedTips;
    return report;
}

}  // namespace pcskeleton
