#include "meshlab_terms.h"

namespace pcskeleton::meshlab {

QString parameterLabel(Parameter parameter) {
    switch (parameter) {
        case Parameter::NeighbourCount: return "Neighbours (k)";
        case Parameter::InitialContractionWeight: return "Initial contraction weight W_L0";
        case Parameter::InitialAttractionWeight: return "Initial attraction weight W_H0";
        case Parameter::ContractionScale: return "Contraction scale s_L";
        case Parameter::MaxContractionWeight: return "Maximum W_L";
        case Parameter::MaxAttractionWeight: return "Maximum W_H";
        case Parameter::LaplacianRowLimit: return "Laplacian row limit";
        case Parameter::MaxIterations: return "Maximum iterations";
        case Parameter::TerminationThreshold: return "Termination threshold";
        case Parameter::NodeSpacing: return "Node spacing (fraction of diagonal)";
        case Parameter::Refinement: return "Refine: remove spurs and spurious loops";
        case Parameter::Resolution: return "Grid resolution";
        case Parameter::SmoothWeight: return "Smoothness weight (w1)";
        case Parameter::SurfaceWeight: return "Surface weight (w2)";
        case Parameter::SkeletonWeight: return "Skeleton weight (w3)";
        case Parameter::OutsideWeight: return "Outside weight (w4)";
        case Parameter::OutsideDistance: return "Outside distance K (radii)";
        case Parameter::OutlierDetection: return "Detect outliers";
        case Parameter::OutlierIsolation: return "Outlier isolation (spacings)";
        case Parameter::OutlierLocalFactor: return "Outlier local factor";
        case Parameter::OutlierClusterShare: return "Outlier cluster share";
        case Parameter::DenoisingPasses: return "Denoising passes";
        case Parameter::LinkLimit: return "Stretched-link limit (node spacings)";
        case Parameter::GapLimit: return "Gap limit (node spacings)";
        case Parameter::LoopOpening: return "Narrow-loop opening (tube radii)";
        case Parameter::LoopClearance: return "Narrow-loop clearance (fraction of radius)";
        case Parameter::GapStretch: return "Gap stretch (end radii)";
        case Parameter::ContractedPoints: return "the number of contracted points (untick 'Full resolution')";
        case Parameter::SkeletonTopology: return "Keep the skeleton's topology";
    }
    return {};
}

namespace {

// The limits the dialogs leave out (a dialog taller than the screen hides its Apply
// button): where a message names one, it says where it is set.
std::string outsideTheDialogs(Parameter parameter) {
    switch (parameter) {
        case Parameter::OutlierIsolation: return "--outlier-isolation";
        case Parameter::OutlierLocalFactor: return "--outlier-local";
        case Parameter::OutlierClusterShare: return "--outlier-cluster";
        case Parameter::GapStretch: return "--gap-stretch";
        default: return {};
    }
}

// Quoted, so that a dialog field reads as one in the middle of a sentence.
std::string quotedLabel(Parameter parameter) {
    const std::string label = "'" + parameterLabel(parameter).toStdString() + "'";
    const std::string option = outsideTheDialogs(parameter);
    return option.empty() ? label : label + " (not in this dialog: pcskeleton " + option + ", or the Python module)";
}

std::string filterStep(Step step) {
    switch (step) {
        case Step::RemoveOutliers:
            return "remove outliers first (Filters > Selection > Select Outliers, then Delete Selected Vertices)";
        case Step::RemoveNonFinitePoints: return "remove them first (Filters > Cleaning and Repairing)";
        case Step::ComputeSkeleton:
            return "use the skeleton computed from these points (Filters > Point Set > Compute Curve Skeleton)";
        case Step::DeleteNodes: return "delete them in Edit Skeleton";
        case Step::MergeNodes: return "merge their nodes in Edit Skeleton";
        case Step::SetNodeRadii:
            return "set the radii with Edit Skeleton (+/-) or Filters > Point Set > Skeleton: Set Radius of Selected "
                   "Nodes";
        case Step::ContractAgain: return "contract the points again (Contract Point Cloud (Laplacian))";
    }
    return {};
}

std::string editorStep(Step step) {
    switch (step) {
        case Step::DeleteNodes: return "select them and press Del";
        case Step::MergeNodes: return "select their nodes and press M";
        case Step::SetNodeRadii: return "select the nodes and press + or -";
        default: return filterStep(step);
    }
}

}  // namespace

const Terms& filterTerms() {
    static const Terms terms{quotedLabel, filterStep};
    return terms;
}

const Terms& editorTerms() {
    static const Terms terms{quotedLabel, editorStep};
    return terms;
}

QString describeForMeshLab(const Problem& problem, const Terms& terms) {
    return QString::fromStdString(describe(problem, terms));
}

}  // namespace pcskeleton::meshlab
