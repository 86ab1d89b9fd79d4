#include "pcskeleton/core/advice.h"

#include <algorithm>
#include <cctype>

namespace pcskeleton {

bool Problem::suggests(const Remedy& remedy) const {
    return std::find(remedies.begin(), remedies.end(), remedy) != remedies.end();
}

namespace {

std::string libraryParameterName(Parameter p) {
    switch (p) {
        case Parameter::NeighbourCount: return "k";
        case Parameter::InitialContractionWeight: return "the initial contraction weight W_L0";
        case Parameter::InitialAttractionWeight: return "the initial attraction weight W_H0";
        case Parameter::ContractionScale: return "the contraction scale s_L";
        case Parameter::MaxContractionWeight: return "the maximum contraction weight";
        case Parameter::MaxAttractionWeight: return "the maximum attraction weight";
        case Parameter::LaplacianRowLimit: return "the Laplacian row limit";
        case Parameter::MaxIterations: return "the maximum iterations";
        case Parameter::TerminationThreshold: return "the termination threshold";
        case Parameter::NodeSpacing: return "the node spacing";
        case Parameter::Refinement: return "refinement";
        case Parameter::Resolution: return "the grid resolution";
        case Parameter::SmoothWeight: return "the smoothness weight";
        case Parameter::SurfaceWeight: return "the surface weight";
        case Parameter::SkeletonWeight: return "the skeleton weight";
        case Parameter::OutsideWeight: return "the outside weight";
        case Parameter::OutsideDistance: return "K";
    }
    return "a parameter";
}

std::string libraryStep(Step s) {
    switch (s) {
        case Step::RemoveOutliers: return "remove outliers first";
        case Step::RemoveNonFinitePoints: return "remove them first";
        case Step::ComputeSkeleton: return "compute the skeleton of these points first";
        case Step::DeleteNodes: return "delete them in a skeleton editor";
        case Step::MergeNodes: return "merge their nodes in a skeleton editor";
        case Step::SetNodeRadii: return "set the node radii in a skeleton editor";
    }
    return "edit the input";
}

const char* verb(Remedy::Kind kind) {
    switch (kind) {
        case Remedy::Kind::Raise: return "raise ";
        case Remedy::Kind::Lower: return "lower ";
        case Remedy::Kind::TurnOn: return "turn on ";
        case Remedy::Kind::Take: return "";
    }
    return "";
}

std::string capitalised(std::string text) {
    if (!text.empty()) text[0] = char(std::toupper(static_cast<unsigned char>(text[0])));
    return text;
}

}  // namespace

const Terms& libraryTerms() {
    static const Terms terms{libraryParameterName, libraryStep};
    return terms;
}

std::string describeRemedies(const std::vector<Remedy>& remedies, const Terms& terms) {
    std::string text;
    for (std::size_t i = 0; i < remedies.size(); ++i) {
        const Remedy& r = remedies[i];
        if (i > 0) text += i + 1 < remedies.size() ? ", " : (remedies.size() > 2 ? ", or " : " or ");
        const bool sameVerb = i > 0 && r.kind != Remedy::Kind::Take && r.kind == remedies[i - 1].kind;
        if (!sameVerb) text += verb(r.kind);
        text += r.kind == Remedy::Kind::Take ? terms.step(r.step) : terms.parameter(r.parameter);
    }
    return text;
}

std::string describe(const Problem& problem, const Terms& terms) {
    if (problem.remedies.empty()) return problem.description;
    const std::string remedies = describeRemedies(problem.remedies, terms);
    const bool sentence = !problem.description.empty() && problem.description.back() == '.';
    return sentence ? problem.description + " " + capitalised(remedies) + "."
                    : problem.description + ": " + remedies + ".";
}

}  // namespace pcskeleton
