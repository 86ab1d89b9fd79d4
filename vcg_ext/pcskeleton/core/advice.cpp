#include "pcskeleton/core/advice.h"

#include "pcskeleton/core/parameter_table.h"

#include <algorithm>
#include <cctype>

namespace pcskeleton {

bool Problem::suggests(const Remedy& remedy) const {
    return std::find(remedies.begin(), remedies.end(), remedy) != remedies.end();
}

namespace {

std::string libraryParameterName(Parameter p) { return parameterInfo(p).words; }

std::string libraryStep(Step s) {
    switch (s) {
        case Step::RemoveOutliers: return "remove outliers first";
        case Step::RemoveNonFinitePoints: return "remove them first";
        case Step::ComputeSkeleton: return "compute the skeleton of these points first";
        case Step::DeleteNodes: return "delete them in a skeleton editor";
        case Step::MergeNodes: return "merge their nodes in a skeleton editor";
        case Step::SetNodeRadii: return "set the node radii in a skeleton editor";
        case Step::ContractAgain: return "contract the input again";
    }
    return "edit the input";
}

std::string verb(Remedy::Kind kind) {
    switch (kind) {
        case Remedy::Kind::Raise: return "raise ";
        case Remedy::Kind::Lower: return "lower ";
        case Remedy::Kind::TurnOn: return "turn on ";
        case Remedy::Kind::TurnOff: return "turn off ";
        case Remedy::Kind::Take: return "";
    }
    return "";
}

// A sentence starts with a capital, unless it starts with a symbol ("k", "--sl").
std::string capitalised(std::string text) {
    const bool word = text.size() > 1 && std::isalpha(static_cast<unsigned char>(text[1]));
    if (word) text[0] = char(std::toupper(static_cast<unsigned char>(text[0])));
    return text;
}

}  // namespace

const Terms& libraryTerms() {
    static const Terms terms{libraryParameterName, libraryStep};
    return terms;
}

std::string describeRemedies(const std::vector<Remedy>& remedies, const Terms& terms) {
    // Consecutive remedies of the same kind share their verb: "raise A or B".
    std::vector<std::string> groups;
    for (std::size_t i = 0; i < remedies.size(); ++i) {
        const Remedy& r = remedies[i];
        const std::string object = r.kind == Remedy::Kind::Take ? terms.step(r.step) : terms.parameter(r.parameter);
        if (i > 0 && r.kind != Remedy::Kind::Take && r.kind == remedies[i - 1].kind) {
            groups.back() += " or " + object;
        } else {
            groups.push_back(verb(r.kind) + object);
        }
    }
    std::string text;
    for (std::size_t g = 0; g < groups.size(); ++g) {
        if (g > 0) text += g + 1 < groups.size() ? ", " : ", or ";
        text += groups[g];
    }
    return text;
}

std::string describe(const Problem& problem, const Terms& terms) {
    const std::string description =
        problem.subject ? capitalised(terms.parameter(*problem.subject)) + " " + problem.description : problem.description;
    if (problem.remedies.empty()) return description;
    const std::string remedies = describeRemedies(problem.remedies, terms);
    const bool sentence = !description.empty() && description.back() == '.';
    return sentence ? description + " " + capitalised(remedies) + "." : description + ": " + remedies + ".";
}

}  // namespace pcskeleton
