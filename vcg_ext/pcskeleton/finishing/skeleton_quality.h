// The quality report of a skeleton run: what was computed, whether contraction did its
// job, and the failure modes a user should know about before trusting the result.
//
// Checks (each one names the parameters or steps that usually fix it, as remedies that each
// front end words in its own terms):
// - points that did not contract: their contracted position is farther from the skeleton
//   than the radius there (outliers, or parts too flat or thick to contract);
// - parts of the input (connected through the 1-rings) whose nodes have no bone: they
//   collapsed to a point and gave no skeleton; and isolated nodes in general (outliers);
// - nodes outside the shape: all of a node's points lie on one side of it (the mean of
//   the unit vectors towards them is longer than 0.8), as when the centre of a bent part's
//   points falls outside the part;
// - nodes away from their data (data_support.h), which no step should leave;
// - spurs and spurious cycles (criteria in skeleton_structure.h).
#pragma once

#include "pcskeleton/contraction/laplacian_contraction.h"
#include "pcskeleton/skeleton/skeleton_graph.h"
#include "pcskeleton/finishing/node_recentering.h"
#include "pcskeleton/skeleton/sheet_collapse.h"
#include "pcskeleton/finishing/gap_bridging.h"
#include "pcskeleton/finishing/skeleton_refinement.h"
#include "pcskeleton/finishing/tip_extension.h"
#include "pcskeleton/core/advice.h"

#include <optional>
#include <string>
#include <vector>

namespace pcskeleton {

struct QualityWarning {
    enum class Kind {
        IterationLimit,
        NumericalFailure,
        ManyOutliers,
        UncontractedPoints,
        PartsWithoutBone,
        IsolatedNodes,
        NodesOutside,
        NodesAwayFromData,
        Spurs,
        SpuriousCycles,
        ContactLoops,
        FilledLoops,
    };
    Kind kind;
    Problem problem;
};

struct SkeletonQuality {
    SkeletonTopology topology;
    double nodeSpacing = 0.0;  // the thinning radius, input units

    // Empty when unknown: thinned from a saved layer of contracted points.
    std::optional<ContractionOutcome> contraction;

    std::size_t points = 0;         // contracted: all of the input, or its subsample (multi-resolution)
    std::size_t inputPoints = 0;    // of the input; more than `points` when a subsample was contracted
    double subsampleCellSize = 0.0; // the subsample's cube side (point_subsampling.h), input units
    std::size_t inputOutliers = 0;  // multi-resolution: of the input, found before subsampling
    std::size_t outliers = 0;       // set aside before the 1-rings: no node
    std::size_t uncontractedPoints = 0;
    int inputParts = 0;             // connected parts of the input through the 1-rings
    int partsWithoutBone = 0;       // of which gave no bone
    std::size_t pointsWithoutBone = 0;
    std::size_t pointsOfIsolatedNodes = 0;  // points owned by nodes without a bone
    std::vector<int> nodesOutside;  // nodes with all their points on one side
    // Nodes of the finished skeleton that do not stay with their data (data_support.h). The
    // finishing steps refuse such moves, so this stays empty unless a step has a bug.
    std::vector<int> nodesAwayFromData;
    std::vector<std::vector<int>> spurs;           // node paths, tip first
    std::vector<std::vector<int>> spuriousCycles;  // node cycles
    // Narrow loops whose bone crosses the surface (skeleton_structure.h, contactLoops),
    // sought only when refinement, which opens them, did not run.
    std::vector<std::vector<int>> contactLoops;
    // Loops whose own points cover their inside (skeleton_structure.h, filledLoops), sought
    // likewise.
    std::vector<std::vector<int>> filledLoops;

    // The steps after contraction that are not the paper's; each empty when it was off.
    std::optional<SheetCollapseReport> sheets;
    std::optional<RecenteringReport> recentering;
    std::optional<RefinementReport> refinement;
    std::optional<GapBridgingReport> gapBridging;
    std::optional<TipExtensionReport> tipExtension;

    // One per problem found, each with what to change; empty when none.
    std::vector<QualityWarning> warnings() const;
};

// The report's first lines: the skeleton's numbers, the contraction, the input, the
// post-processing.
std::string describeFindings(const SkeletonQuality& quality);

// The whole report: the findings, then one "Warning: ..." line per warning, its remedies
// worded in `terms` (or "No warnings.").
std::string describe(const SkeletonQuality& quality, const Terms& terms = libraryTerms());

// The checks on `skeleton` (input frame), computed from the contraction's own data:
// `cloud` and its `rings`, and `contracted`, the contracted distinct points in the
// normalised frame. Fills everything but the contraction and post-processing fields.
SkeletonQuality assessSkeleton(const SkeletonGraph& skeleton, const NormalizedCloud& cloud, const OneRings& rings,
                               const PointList& contracted, double nodeSpacing);

}  // namespace pcskeleton
