// Problems and their remedies, worded in the library's terms and in a front end's.
#include <pcskeleton/core/advice.h>
#include <pcskeleton/core/errors.h>

#include <gtest/gtest.h>

namespace pcskeleton {
namespace {

// A front end that names parameters by option and steps by a tag.
const Terms& optionTerms() {
    static const Terms terms{[](Parameter p) { return p == Parameter::MaxIterations ? "--iterations" : "--other"; },
                             [](Step) { return std::string("do it here"); }};
    return terms;
}

TEST(Advice, RemediesOfOneKindShareTheirVerb) {
    const std::vector<Remedy> remedies{Remedy::raise(Parameter::MaxIterations), Remedy::raise(Parameter::ContractionScale)};
    EXPECT_EQ(describeRemedies(remedies, libraryTerms()), "raise the maximum iterations or the contraction scale s_L");
    EXPECT_EQ(describeRemedies({Remedy::take(Step::RemoveOutliers), Remedy::raise(Parameter::NeighbourCount),
                                Remedy::raise(Parameter::MaxIterations)},
                               libraryTerms()),
              "remove outliers first, or raise k or the maximum iterations");
    EXPECT_EQ(describeRemedies({Remedy::turnOn(Parameter::Refinement), Remedy::take(Step::DeleteNodes),
                                Remedy::raise(Parameter::NeighbourCount)},
                               optionTerms()),
              "turn on --other, do it here, or raise --other");
    EXPECT_EQ(describeRemedies({}, libraryTerms()), "");
}

TEST(Advice, ASentenceIsFollowedByASecondOneAFragmentByAColon) {
    const Problem sentence{"Too few points.", {Remedy::lower(Parameter::NeighbourCount)}};
    EXPECT_EQ(describe(sentence), "Too few points. Lower k.");  // "k" is a symbol: not capitalised
    const Problem fragment{"Contraction stopped early", {Remedy::raise(Parameter::MaxIterations)}};
    EXPECT_EQ(describe(fragment), "Contraction stopped early: raise the maximum iterations.");
    EXPECT_EQ(describe(fragment, optionTerms()), "Contraction stopped early: raise --iterations.");
    EXPECT_EQ(describe(Problem{"Nothing to do."}), "Nothing to do.");
}

TEST(Advice, ARefusedParameterIsNamedInTheFrontEndsTerms) {
    const Problem p = Problem::aboutParameter(Parameter::ContractionScale, "must be at least 1.");
    EXPECT_EQ(describe(p), "The contraction scale s_L must be at least 1.");
    const Problem q = Problem::aboutParameter(Parameter::MaxIterations, "must be at least 1.");
    EXPECT_EQ(describe(q, optionTerms()), "--iterations must be at least 1.");
}

TEST(Advice, ExceptionsCarryTheProblemAndSayItInTheLibrarysTerms) {
    try {
        throw InvalidInput("The layer is empty.", {Remedy::take(Step::ComputeSkeleton)});
    } catch (const InvalidInput& e) {
        EXPECT_EQ(std::string(e.what()), describe(e.problem()));
        EXPECT_TRUE(e.problem().suggests(Remedy::take(Step::ComputeSkeleton)));
        EXPECT_FALSE(e.problem().suggests(Remedy::take(Step::DeleteNodes)));
        EXPECT_EQ(describe(e.problem(), optionTerms()), "The layer is empty. Do it here.");
    }
    // A caller's bug is not the user's problem: a different type, not an InvalidInput.
    EXPECT_THROW(throw CallerError("bug"), std::logic_error);
}

TEST(Advice, TheLibrarysOwnWordsNameNoFrontEnd) {
    for (int s = 0; s <= int(Step::ContractAgain); ++s) {
        const std::string text = libraryTerms().step(Step(s));
        EXPECT_FALSE(text.empty());
        for (const char* frontEnd : {"Filters >", "Edit Skeleton", "MeshLab", "--"})
            EXPECT_EQ(text.find(frontEnd), std::string::npos) << text;
    }
    for (int p = 0; p <= int(Parameter::OutlierClusterShare); ++p) EXPECT_FALSE(libraryTerms().parameter(Parameter(p)).empty());
}

}  // namespace
}  // namespace pcskeleton
