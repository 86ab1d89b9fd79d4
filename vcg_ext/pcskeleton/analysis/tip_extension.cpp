#include "pcskeleton/analysis/tip_extension.h"

#include "pcskeleton/skeleton/skeleton_structure.h"

#include <algorithm>

namespace pcskeleton {

namespace {

constexpr double kTubeRadii = 1.5;

// The limb's direction at its tip: from the first node at least two node spacings back
// (or the limb's other end) to the tip.
Point tipDirection(const SkeletonGraph& skeleton, const Limb& limb, double nodeSpacing) {
    const Point& tip = skeleton.nodes[limb.path.front()];
    int back = limb.path.back();
    for (int n : limb.path) {
        if ((skeleton.nodes[n] - tip).norm() >= 2.0 * nodeSpacing) {
            back = n;
            break;
        }
    }
    return (tip - skeleton.nodes[back]).normalized();
}

}  // namespace

TipExtensionReport extendTips(SkeletonGraph& skeleton, const PointList& points, double nodeSpacing) {
    const std::vector<std::vector<int>> pointsOf = pointsOfNodes(skeleton);
    TipExtensionReport report;
    for (const Limb& limb : tipLimbs(skeleton)) {
        const int tip = limb.path.front();
        if (isSpur(skeleton, limb, nodeSpacing) || pointsOf[tip].empty()) continue;
        const Point direction = tipDirection(skeleton, limb, nodeSpacing);
        if (!direction.allFinite()) continue;  // coincident nodes: no direction to extend in
        const Point tipPosition = skeleton.nodes[tip];
        struct Offset {
            double along, across;  // of a tip point, relative to the limb's axis through the tip
        };
        std::vector<Offset> offsets;
        for (int i : pointsOf[tip]) {
            const Point offset = points[i] - tipPosition;
            const double along = offset.dot(direction);
            offsets.push_back({along, (offset - along * direction).norm()});
        }

        // Only points within the limb's tube count: an outlier or a noisy point off to the
        // side must not pull the end out.
        double reach = 0.0;
        for (const Offset& o : offsets) {
            if (o.across <= kTubeRadii * skeleton.radii[tip]) reach = std::max(reach, o.along);
        }
        if (reach <= 0.1 * nodeSpacing) continue;

        const double endZone = reach - 0.25 * skeleton.radii[tip];
        double thickness = 0.0;
        int endPoints = 0;
        for (const Offset& o : offsets) {
            if (o.along >= endZone) thickness += o.across, ++endPoints;
        }
        thickness = endPoints > 0 ? thickness / endPoints : 0.0;
        if (!isPositiveFinite(thickness)) thickness = 0.5 * skeleton.radii[tip];

        skeleton.nodes.push_back(tipPosition + reach * direction);
        skeleton.radii.push_back(std::min(thickness, skeleton.radii[tip]));
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
