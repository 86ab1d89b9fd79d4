#include "meshlab_terms.h"

#include <pcskeleton/core/parameter_table.h>
#include <pcskeleton/version.h>

namespace pcskeleton::meshlab {

QString parameterLabel(Parameter parameter) { return parameterInfo(parameter).label; }

namespace {

// Quoted, so that a dialog field reads as one in the middle of a sentence; a parameter the
// dialogs do not have (their scripts must keep their fields) says where it is set.
std::string quotedLabel(Parameter parameter) {
    const ParameterInfo& p = parameterInfo(parameter);
    const std::string label = "'" + std::string(p.label) + "'";
    if (p.meshlabName) return label;
    std::string option = p.name;
    for (char& c : option) c = c == '_' ? '-' : c;
    return label + " (not in this dialog: pcskeleton --" + option + ", or the Python module)";
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

QString pluginVendor() { return QStringLiteral("pcskeleton " PCSKELETON_VERSION); }

QString withVersion(const QString& description) { return description + "<br><br>" + pluginVendor(); }

QString describeForMeshLab(const Problem& problem, const Terms& terms) {
    return QString::fromStdString(describe(problem, terms));
}

}  // namespace pcskeleton::meshlab
