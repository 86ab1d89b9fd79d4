// What the library says about a problem, without naming any front end's menus or options.
// A problem is a description plus its remedies, each a parameter to turn or a step to take;
// the MeshLab plugin, the command line and the editor each word the remedies in their own
// terms (a dialog field, `--refine`, a key), through a Terms object.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace pcskeleton {

// Every parameter a user can set; core/parameter_table.h describes each.
enum class Parameter {
    NeighbourCount,
    InitialContractionWeight,
    InitialAttractionWeight,
    ContractionScale,
    MaxContractionWeight,
    MaxAttractionWeight,
    LaplacianRowLimit,
    MaxIterations,
    TerminationThreshold,
    MedialPull,
    OutlierDetection,
    OutlierIsolation,
    OutlierLocalFactor,
    OutlierClusterShare,
    DenoisingPasses,
    FacingWalls,
    ContractedPoints,
    FullResolution,
    MemoryLimit,
    NodeSpacing,
    ExtendTips,
    Sheets,
    Recentre,
    Refinement,
    GapLimit,
    LinkLimit,
    LoopOpening,
    LoopClearance,
    GapStretch,
    MinHole,
    Resolution,
    SmoothWeight,
    SurfaceWeight,
    SkeletonWeight,
    OutsideWeight,
    OutsideDistance,
    SkeletonTopology,  // the reconstruction keeps the skeleton's topology
    PointWeights,      // the reconstruction weighs noisy points less
    VertexFitting,     // the reconstruction's vertices move onto a local fit of the points
};

// Steps the user takes outside the computation that found the problem.
enum class Step {
    RemoveOutliers,         // from the input points
    RemoveNonFinitePoints,  // from the input points
    ComputeSkeleton,        // of the points
    DeleteNodes,            // the nodes the problem names, by hand
    MergeNodes,             // the nodes the problem names, by hand
    SetNodeRadii,           // of the skeleton, by hand
    ContractAgain,          // the input, because its contracted points do not fit it
};

struct Remedy {
    enum class Kind { Raise, Lower, TurnOn, TurnOff, Take };
    Kind kind;
    Parameter parameter;  // Raise, Lower, TurnOn, TurnOff
    Step step;            // Take

    static Remedy raise(Parameter p) { return {Kind::Raise, p, Step{}}; }
    static Remedy lower(Parameter p) { return {Kind::Lower, p, Step{}}; }
    static Remedy turnOn(Parameter p) { return {Kind::TurnOn, p, Step{}}; }
    static Remedy turnOff(Parameter p) { return {Kind::TurnOff, p, Step{}}; }
    static Remedy take(Step s) { return {Kind::Take, Parameter{}, s}; }
    bool operator==(const Remedy& o) const {
        return kind == o.kind && (kind == Kind::Take ? step == o.step : parameter == o.parameter);
    }
};

struct Problem {
    Problem() = default;
    Problem(std::string description_, std::vector<Remedy> remedies_ = {}, std::optional<Parameter> subject_ = {})
        : description(std::move(description_)), remedies(std::move(remedies_)), subject(subject_) {}

    // What is wrong, in words that hold in every front end. A full sentence (ending in '.')
    // is followed by the remedies as a new sentence; otherwise they follow a colon.
    std::string description;
    std::vector<Remedy> remedies;
    // For a parameter's value that is refused: the description is the requirement ("must be
    // at least 1."), preceded by the parameter's name in the front end's terms.
    std::optional<Parameter> subject;

    static Problem aboutParameter(Parameter p, std::string requirement) { return {std::move(requirement), {}, p}; }
    bool suggests(const Remedy& remedy) const;
};

// A front end's words: each parameter's name as its users see it ("--iterations",
// "Maximum iterations"), and each step as an imperative phrase ("delete them in Edit Skeleton").
struct Terms {
    std::function<std::string(Parameter)> parameter;
    std::function<std::string(Step)> step;
};

// The library's own words, for callers of the library and its exceptions' what().
const Terms& libraryTerms();

// "raise the maximum iterations or the contraction scale s_L" (consecutive remedies of the
// same kind share their verb); empty for no remedies.
std::string describeRemedies(const std::vector<Remedy>& remedies, const Terms& terms);

// The description and its remedies as one sentence or two.
std::string describe(const Problem& problem, const Terms& terms = libraryTerms());

}  // namespace pcskeleton
