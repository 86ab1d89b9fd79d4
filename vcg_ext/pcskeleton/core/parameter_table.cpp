#include "pcskeleton/core/parameter_table.h"

#include <algorithm>
#include <stdexcept>

namespace pcskeleton {

namespace {

using V = ValueType;
using S = Stage;
constexpr bool kAdvanced = true, kCommon = false;
constexpr bool kInverted = true, kStraight = false;
// MeshLab 2020.09's meshlabserver runs a script only if it lists exactly the filter's fields,
// so the dialogs keep the fields their scripts have; these parameters are set elsewhere.
constexpr const char* kNotInTheDialogs = nullptr;

const std::vector<ParameterInfo> kTable = {
    // ---- Contraction (paper steps 1-3) ----
    {Parameter::NeighbourCount, "k", V::Integer, S::Contraction, kCommon, kStraight,
     "k", "Neighbours k (0 = automatic)", "k",
     "Nearest neighbours whose tangent-plane Delaunay triangulation gives each point its 1-ring; 0 = automatic: "
     "1.2% of the points, between 20 and 30 (below 600 points a 30th of them, at least 8); the paper's pipeline "
     "takes the paper's rule, between 8 and 30. Raise it for noisy scans; lower it if close-by parts (fingers, claws) "
     "get connected."},
    {Parameter::InitialContractionWeight, "wl", V::Real, S::Contraction, kCommon, kStraight,
     "the initial contraction weight W_L0", "Initial contraction weight W_L0 (0 = automatic)", "contractionWeight",
     "Strength of the Laplacian (shrinking) term in the first iteration; 0 = automatic: 1/(5 S0), S0 being the mean "
     "1-ring size. Too high pulls thin parts into thick ones (paper Fig. 4d); too low leaves tips sticking out of the "
     "shape (Fig. 4a)."},
    {Parameter::ContractionScale, "sl", V::Real, S::Contraction, kCommon, kStraight,
     "the contraction scale s_L", "Contraction scale s_L", "contractionScale",
     "W_L is multiplied by this after every iteration (the paper's 3). Use 2 for shapes with thin parts between "
     "thick ones (paper Fig. 10), at the cost of an extra iteration."},
    {Parameter::MaxIterations, "iterations", V::Integer, S::Contraction, kCommon, kStraight,
     "the maximum iterations", "Maximum iterations", "maxIterations",
     "Contraction stops after this many iterations at the latest (most clouds converge in under 5); raise it if "
     "the report says the limit was reached."},
    {Parameter::InitialAttractionWeight, "wh", V::Real, S::Contraction, kAdvanced, kStraight,
     "the initial attraction weight W_H0", "Initial attraction weight W_H0", "attractionWeight",
     "How strongly points are held at their positions; acts against W_L0 (paper Fig. 4e-h)."},
    {Parameter::MaxContractionWeight, "max_wl", V::Real, S::Contraction, kAdvanced, kStraight,
     "the maximum contraction weight", "Maximum W_L", "maxContractionWeight",
     "Upper limit of the contraction weight W_L, for numerical stability."},
    {Parameter::MaxAttractionWeight, "max_wh", V::Real, S::Contraction, kAdvanced, kStraight,
     "the maximum attraction weight", "Maximum W_H", "maxAttractionWeight",
     "Upper limit of a point's attraction weight (it grows as the point's 1-ring shrinks)."},
    {Parameter::LaplacianRowLimit, "row_limit", V::Real, S::Contraction, kAdvanced, kStraight,
     "the Laplacian row limit", "Laplacian row limit", "laplacianRowLimit",
     "A Laplacian row whose weights add up to more than this is scaled down: a guard against the huge cotangents "
     "of nearly flat 1-ring triangles."},
    {Parameter::TerminationThreshold, "threshold", V::Real, S::Contraction, kAdvanced, kStraight,
     "the termination threshold", "Termination threshold", "terminationThreshold",
     "Contraction stops when the total 1-ring size shrank by less than this fraction of its initial value in the "
     "last iteration."},
    {Parameter::MedialPull, "medial_pull", V::Real, S::Contraction, kAdvanced, kStraight,
     "the medial pull W_M", "Medial pull W_M", kNotInTheDialogs,
     "Pull each point during contraction towards the centre of the largest empty ball touching it from inside "
     "(its medial point), with this weight beside W_H; 1 if a ring or handle whose hole is narrow next to its tube "
     "comes out without its loop. It costs time and can pull points of close parts off their own part's middle. Points whose inside is open (a one-sided scan) are not pulled. 0 = no pull "
     "(the paper's)."},

    // ---- Which points are contracted (not in the paper) ----
    {Parameter::OutlierDetection, "keep_outliers", V::Switch, S::PointCleaning, kCommon, kInverted,
     "outlier detection", "Detect outliers", "detectOutliers",
     "Contract every point, as the paper does. By default points that do not belong to the sampled surface "
     "(isolated points, small sparse clusters, judged against the cloud's own spacing) are set aside and get no "
     "node (-1 in the correspondence); the input is not changed."},
    {Parameter::DenoisingPasses, "denoise", V::Integer, S::PointCleaning, kCommon, kStraight,
     "the denoising passes", "Denoising passes (-1 = automatic)", "denoisePasses",
     "Contract a copy of the points denoised by this many passes of projection onto the plane of each point's k "
     "nearest neighbours (the nodes and radii still come from the points as given): -1 = automatic, a few passes "
     "if the cloud is noisy (its surface noise is in the report), none if it is clean; 0 = never (the paper's); "
     "a positive number: that many passes always."},
    {Parameter::FacingWalls, "facing_walls", V::Switch, S::PointCleaning, kAdvanced, kStraight,
     "the facing walls", "Keep facing walls apart", kNotInTheDialogs,
     "Leave out of each point's 1-ring the neighbours on another part's wall that faces its own across a gap (an "
     "arm beside a body, two legs side by side), so that contraction does not pull the parts into one; which side "
     "is out comes from each point's surface curvature, and where noise hides it the point keeps every neighbour. "
     "Off: every one of the k nearest may join the 1-ring (the paper's)."},
    {Parameter::OutlierIsolation, "outlier_isolation", V::Real, S::PointCleaning, kAdvanced, kStraight,
     "the outlier isolation factor", "Outlier isolation (spacings)", kNotInTheDialogs,
     "A point whose 8th nearest neighbour is farther than this many typical spacings is an outlier; raise it if "
     "sparse parts of the shape are taken for outliers."},
    {Parameter::OutlierLocalFactor, "outlier_local", V::Real, S::PointCleaning, kAdvanced, kStraight,
     "the outlier local factor", "Outlier local factor", kNotInTheDialogs,
     "A point whose 8th nearest neighbour is farther than this many times that of its neighbours (their upper "
     "quartile) is an outlier; lower it to find outliers closer to the surface."},
    {Parameter::OutlierClusterShare, "outlier_cluster", V::Real, S::PointCleaning, kAdvanced, kStraight,
     "the outlier cluster share", "Outlier cluster share", kNotInTheDialogs,
     "Groups of points holding less than this share of the cloud are outlier clusters; 0 keeps every group."},

    // ---- How many points are contracted (not in the paper) ----
    {Parameter::ContractedPoints, "contracted_points", V::Integer, S::Resolution, kAdvanced, kStraight,
     "the number of contracted points", "Contracted points at most", kNotInTheDialogs,
     "A cloud of more points is contracted through a subsample of at most this many, at least 100 (unless at full "
     "resolution). "
     "Raise it for fine detail in huge scans. Up to 20000 the skeleton is the same on every CPU; above, a faster "
     "solver's result may differ in its last digits from one CPU to another."},
    {Parameter::FullResolution, "full_resolution", V::Switch, S::Resolution, kCommon, kStraight,
     "full resolution", "Full resolution", "fullResolution",
     "Contract every point, as the paper does (about 2.7 KB of memory per point). By default a larger cloud is "
     "contracted through a well-spread subsample (one point per cube of a grid): seconds instead of minutes at a "
     "million points; every point still gets its node and the radii come from all points."},
    {Parameter::MemoryLimit, "memory_limit", V::Real, S::Resolution, kAdvanced, kStraight,
     "the memory limit", "Memory limit in GB (0 = automatic)", kNotInTheDialogs,
     "Work estimated to need more than this many GB is refused before it starts; 0 = automatic: 80% of the "
     "machine's memory, or less if the process is limited (ulimit -v, a container)."},

    // ---- Thinning (paper steps 4-5) and what follows ----
    {Parameter::NodeSpacing, "node_spacing", V::Real, S::Thinning, kCommon, kStraight,
     "the node spacing", "Node spacing (fraction of diagonal)", "sampleRadius",
     "Radius of the balls that sample the contracted points into nodes, as a fraction of the bounding-box diagonal "
     "(the paper's 0.02). Larger: fewer nodes, and parts or holes closer than this merge; smaller: more nodes, and "
     "noise may survive as short spurs or tiny loops.",
     "radius"},
    {Parameter::ExtendTips, "extend_tips", V::Switch, S::Thinning, kCommon, kStraight,
     "tip extension", "Extend tips to the shape's ends", "extendTips",
     "Extend every limb along its direction to where its tip's points end: contraction pulls the ends of limbs "
     "inwards. Off: the tips stay where contraction left them (the paper's skeleton)."},
    {Parameter::Sheets, "sheets", V::Switch, S::Thinning, kAdvanced, kStraight,
     "the sheets' medial axes", "Move flat sheets onto their medial axes", kNotInTheDialogs,
     "Before thinning, move the points of a wide flat sheet of a single layer that contraction left flat (a "
     "plate, a disc, a bracket's walls: the Laplacian of a flat patch is zero) onto its medial axis within its "
     "plane, so that a plate gives a loop around each hole instead of a hub of long bones. Off: thinning takes "
     "the contracted points as they are (the paper's)."},
    {Parameter::Recentre, "recentre", V::Switch, S::Thinning, kCommon, kStraight,
     "re-centring", "Re-centre nodes of one-sided parts", "recentre",
     "Move a node whose points cover one side of its bone only (a scan from one side, a hole) to the centre of "
     "the circle through them. Off: every node stays at the centre of its points (the paper's)."},
    {Parameter::Refinement, "refine", V::Switch, S::Thinning, kCommon, kStraight,
     "refinement", "Refine: remove spurs and spurious loops", "refine",
     "Clean what noise leaves: limbs shorter than the body is thick where they join, loops smaller than their "
     "tube, junctions closer than the node spacing, bridges of a handful of points between parts that pass close. "
     "Off: the paper's skeleton."},
    {Parameter::GapLimit, "gap_limit", V::Real, S::Thinning, kCommon, kStraight,
     "the gap limit", "Gap limit (node spacings)", "gapLimit",
     "Where a limb's end (a tip, or a corner where it turns into another limb) points at another piece of the "
     "skeleton whose tube is at most this many node spacings ahead, "
     "or a piece that thinned to a single node lies that close to another's tube (an occluded or "
     "missing stretch of the scan), a bone joins them; pieces side by side are never joined. Raise it for wider "
     "gaps, lower it if separate objects get joined; 0 joins nothing (the paper's)."},
    {Parameter::LinkLimit, "link_limit", V::Real, S::Thinning, kAdvanced, kStraight,
     "the stretched-link limit", "Stretched-link limit (node spacings)", "linkLimit",
     "1-ring neighbours whose contracted points ended more than this many node spacings apart were pulled to "
     "different bones (parts that touch, noise across a gap): they connect their nodes only where nothing else "
     "does. Lower it if close parts get false loops; 0: every neighbour pair connects (the paper's)."},
    {Parameter::LoopOpening, "loop_opening", V::Real, S::Thinning, kAdvanced, kStraight,
     "the narrow-loop opening", "Narrow-loop opening (tube radii)", "loopOpening",
     "Refinement opens a loop whose hole is narrower than this many tube radii at its bone longest for its radii, "
     "if that bone passes closer than the narrow-loop clearance to a point (parts that touch, or that noise "
     "joined). Lower it if a real narrow hole is lost; 0 opens none."},
    {Parameter::LoopClearance, "loop_clearance", V::Real, S::Thinning, kAdvanced, kStraight,
     "the narrow-loop clearance", "Narrow-loop clearance (fraction of radius)", "loopClearance",
     "The fraction of its radius within which that bone must pass a point for the loop to be opened (a bone "
     "inside a tube keeps about a radius from its wall). Lower it if a real narrow hole is lost."},
    {Parameter::GapStretch, "gap_stretch", V::Real, S::Thinning, kAdvanced, kStraight,
     "the gap stretch", "Gap stretch (end radii)", kNotInTheDialogs,
     "Refinement cuts a bone that joins two strands straight across the gap between them (on a loop, between "
     "junctions the strands run through), or a limb's end to another part across space without points (an arm "
     "beside the body seen from one side), when it is longer than this many times the radii at its two ends "
     "together. Raise it if a real bone is cut; 0 cuts none."},
    {Parameter::MinHole, "min_hole", V::Real, S::Thinning, kAdvanced, kStraight,
     "the smallest hole", "Smallest hole (node spacings)", kNotInTheDialogs,
     "Refinement opens a loop whose inside the data covers: one in which no disc wider than this many node "
     "spacings (its radius) is free of points (a one-view scan of a rounded part contracts to a ring along its "
     "rim; parts that touch), or across which a limb of the skeleton lies (from one view, a limb in front of "
     "the body hides a hole-shaped strip of it). Lower it if a real small hole is lost; 0 opens none."},

    // ---- Reconstruction (paper Sec. V) ----
    {Parameter::Resolution, "resolution", V::Integer, S::Reconstruction, kCommon, kStraight,
     "the grid resolution", "Grid resolution", "resolution",
     "Grid cells along the longest side. Finer shows more detail; memory and time grow with its cube (about 1 GB "
     "and 10 s at 256 for a ring-shaped object)."},
    {Parameter::SmoothWeight, "smooth_weight", V::Real, S::Reconstruction, kCommon, kStraight,
     "the smoothness weight", "Smoothness weight (w1)", "smoothWeight",
     "w1, the field's smoothness (the integral of its squared Laplacian). Raise it for noisy scans; lower it to "
     "follow the points more closely."},
    {Parameter::SurfaceWeight, "surface_weight", V::Real, S::Reconstruction, kCommon, kStraight,
     "the surface weight", "Surface weight (w2)", "surfaceWeight",
     "w2, how strongly the surface passes through the points (the field is 0 there)."},
    {Parameter::SkeletonWeight, "skeleton_weight", V::Real, S::Reconstruction, kCommon, kStraight,
     "the skeleton weight", "Skeleton weight (w3)", "skeletonWeight",
     "w3, how strongly the field equals minus the node radius along the bones. Raise it if the surface does not "
     "bridge a gap the skeleton crosses; the radius sets how thick the bridge is."},
    {Parameter::OutsideWeight, "outside_weight", V::Real, S::Reconstruction, kCommon, kStraight,
     "the outside weight", "Outside weight (w4)", "outsideWeight",
     "w4, how strongly the field is positive far from the skeleton (a weak hint). Raise it if the surface bulges "
     "into empty space or closes holes the skeleton leaves open."},
    {Parameter::OutsideDistance, "outside_radii", V::Real, S::Reconstruction, kCommon, kStraight,
     "K (outside distance, in radii)", "Outside distance K (radii)", "outsideRadii",
     "Space farther than K node radii from the skeleton counts as outside the shape (the paper's 4). Lower it to "
     "keep gaps open next to thin parts."},
    {Parameter::SkeletonTopology, "data_topology", V::Switch, S::Reconstruction, kCommon, kInverted,
     "the topology guarantee", "Keep the skeleton's topology", "keepSkeletonTopology",
     "The paper's plain fit: the surface may have any handles and parts the points suggest. By default it gets "
     "exactly the skeleton's topology, one closed part per skeleton part and one handle per loop; what else the "
     "points suggest (noise, close parts touching) is cut away."},
    {Parameter::PointWeights, "uniform_point_weights", V::Switch, S::Reconstruction, kAdvanced, kInverted,
     "the noise-adapted point weights", "Weigh noisy points less", "adaptToNoise",
     "Every point weighs w2, as in the paper. By default points whose neighbours scatter across the surface by "
     "more than a grid cell (noise) weigh less, so that noise makes no bumps."},
    {Parameter::VertexFitting, "level_set", V::Switch, S::Reconstruction, kAdvanced, kInverted,
     "the vertex fitting", "Fit the surface to the points", "fitVerticesToPoints",
     "The field's zero level set as it is (the paper's). By default, where there are points, each vertex moves "
     "(by at most a grid cell) onto a smooth local fit of its nearest points; the triangles, and so the topology, "
     "do not change."},
};

}  // namespace

const std::vector<ParameterInfo>& parameterTable() { return kTable; }

const ParameterInfo& parameterInfo(Parameter id) {
    const auto found = std::find_if(kTable.begin(), kTable.end(), [&](const ParameterInfo& p) { return p.id == id; });
    if (found == kTable.end()) throw std::logic_error("a parameter without an entry in the parameter table");
    return *found;
}

const ParameterInfo* parameterNamed(std::string_view name) {
    for (const ParameterInfo& p : kTable) {
        if (name == p.name || (p.formerName && name == p.formerName)) return &p;
    }
    return nullptr;
}

}  // namespace pcskeleton
