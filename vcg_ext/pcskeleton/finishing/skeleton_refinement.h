// Refinement of a computed skeleton, in the spirit of the authors' own post-processing:
// the small artefacts noise leaves are removed. Not the paper's step; on by default
// (SkeletonGraphParameters::refine says why). Criteria: see skeleton_structure.h.
//
// 1. Spurs, redundant limbs and corner limbs are absorbed into the junction they sprout
//    from (which keeps its place).
//    The straggling end of a limb (a few nodes of a few noisy points past its end) is
//    absorbed into the first node that owns enough points (which keeps its place).
// 2. Each spurious cycle (a loop without a hole) collapses to one node at its centre.
//    A loop whose opening is narrower than its tube, and whose most stretched bone (its
//    nodes' balls do not meet) passes through the surface, is two parts that touch or
//    that noise joined: it is opened at that bone (skeleton_structure.h, contactLoops).
//    A stray bridge (a path between junctions, on a loop or between parts side by side,
//    whose nodes own a handful of points) is cut at its far end, and its nodes are
//    absorbed into the junction it then hangs from (which keeps its place). A bone across
//    a gap (straight between two strands whose tubes do not meet along it) is cut; the
//    report counts it as a stray bridge. A loop whose own points cover its inside (no
//    disc wider than RefinementLimits::minHole node spacings free of them: a one-view scan
//    of a rounded part, a limb touching the body), or across which a limb lies (a one-view
//    scan of a limb in front of the body, whose shadow contraction rings), is opened at its
//    most stretched bone (skeleton_structure.h, filledLoops).
// 3. Junctions joined by a path shorter than the node spacing merge into one node at the
//    path's centre.
// Repeated until nothing changes, since each step can expose more. Then, once nothing does,
// a bone over a gap in the data (a limb's end joined to another part across space where
// the data has no points: skeleton_structure.h, bonesOverDataGaps) is cut, counted as a stray
// bridge, and the steps run again. Merged nodes keep all their points and their mean radius.
#pragma once

#include "pcskeleton/skeleton/skeleton_graph.h"
#include "pcskeleton/skeleton/skeleton_structure.h"

#include <string>
#include <vector>

namespace pcskeleton {

struct RefinementReport {
    int spursRemoved = 0, endsTrimmed = 0, cyclesCollapsed = 0, cyclesCut = 0, bridgesCut = 0, junctionsMerged = 0;
    int filledLoopsCut = 0;      // loops whose own points cover their inside (filledLoops)
    int cornerLimbsRemoved = 0;  // limbs out of a bend's outer corner (isCornerLimb)
    std::vector<int> nodeMap;  // per node of the skeleton given: the node it became
    bool changedAnything() const {
        return spursRemoved + cornerLimbsRemoved + endsTrimmed + cyclesCollapsed + cyclesCut + bridgesCut +
                   junctionsMerged + filledLoopsCut >
               0;
    }
};

// "removed 2 spurs and 1 corner limb, trimmed 0 straggling ends, collapsed 1 small loop,
// cut 0 narrow loops, 0 stray bridges, 1 loop over data, merged 0 pairs of close junctions"
std::string describe(const RefinementReport& report);

// `nodeSpacing` is the thinning radius, in the skeleton's units; `points` its input points
// (graph.pointNode's), or empty to keep redundant limbs and narrow loops.
RefinementReport refineSkeleton(SkeletonGraph& skeleton, const PointList& points, double nodeSpacing,
                                const RefinementLimits& refinementLimits = {});

}  // namespace pcskeleton
