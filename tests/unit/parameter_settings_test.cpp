// The parameter table's binding to the parameter structs: every value set with the
// library's own range check, and `paper` meaning one thing.
#include <pcskeleton/parameter_settings.h>

#include <gtest/gtest.h>

namespace pcskeleton {
namespace {

TEST(ParameterSettings, DefaultsReadBackAndEveryValueReachesItsField) {
    Settings s;
    for (const ParameterInfo& p : parameterTable()) {
        const double before = parameterValue(s, p.id);
        EXPECT_EQ(before, defaultValue(p.id)) << p.name;
        // A valid value other than the default: the switch flipped, a number nudged up.
        const double other = p.type == ValueType::Switch ? 1 - before
                             : p.id == Parameter::LoopClearance ? 0.5
                             : p.id == Parameter::NodeSpacing ? 0.03
                             : p.id == Parameter::TerminationThreshold ? 0.02
                             : p.id == Parameter::OutlierClusterShare ? 0.02
                             : p.id == Parameter::Resolution ? 64
                             : p.id == Parameter::DenoisingPasses ? 3
                             : p.id == Parameter::NeighbourCount ? 12
                             : before + 1;
        setParameter(s, p.id, other);
        EXPECT_EQ(parameterValue(s, p.id), other) << p.name;
    }
}

TEST(ParameterSettings, ValuesTheLibraryRefusesAreRefusedWhenSet) {
    Settings s;
    EXPECT_THROW(setParameter(s, Parameter::MaxIterations, 0), InvalidInput);
    EXPECT_THROW(setParameter(s, Parameter::MaxIterations, 2.5), InvalidInput) << "not a whole number";
    EXPECT_THROW(setParameter(s, Parameter::NodeSpacing, 2), InvalidInput);
    EXPECT_THROW(setParameter(s, Parameter::ContractedPoints, 0), InvalidInput);
    EXPECT_THROW(setParameter(s, Parameter::ContractedPoints, 9), InvalidInput)
        << "too few to hold the neighbours contraction needs";
    EXPECT_NO_THROW(setParameter(s, Parameter::ContractedPoints, 100));
    EXPECT_THROW(setParameter(s, Parameter::MemoryLimit, -1), InvalidInput);
    EXPECT_THROW(setParameter(s, Parameter::Resolution, 4), InvalidInput);
    EXPECT_THROW(setParameter(s, Parameter::Refinement, 0.5), InvalidInput);
    try {
        setParameter(s, Parameter::GapStretch, 0.5);
        FAIL() << "a gap stretch of 0.5 was taken";
    } catch (const InvalidInput& e) {
        EXPECT_EQ(e.problem().subject, Parameter::GapStretch);
    }
    EXPECT_EQ(parameterValue(s, Parameter::MaxIterations), defaultValue(Parameter::MaxIterations)) << "unchanged";
}

TEST(ParameterSettings, PaperFirstThenEveryOptionWhateverTheOrder) {
    const Settings paper = settingsFrom(true, {});
    EXPECT_FALSE(paper.skeleton.graph.refine);
    EXPECT_EQ(paper.skeleton.resolution.maxContractedPoints, 0u);
    EXPECT_FALSE(paper.reconstruction.keepSkeletonTopology);
    const Settings refined = settingsFrom(true, {{Parameter::Refinement, 1}, {Parameter::NodeSpacing, 0.03}});
    EXPECT_TRUE(refined.skeleton.graph.refine);
    EXPECT_DOUBLE_EQ(refined.skeleton.graph.nodeSpacing, 0.03);
    EXPECT_FALSE(refined.skeleton.graph.recentre) << "the rest of the paper's pipeline stays";
    // Full resolution wins over a number of contracted points, in either order.
    for (const auto& given : {std::vector<std::pair<Parameter, double>>{{Parameter::FullResolution, 1}, {Parameter::ContractedPoints, 9000}},
                              std::vector<std::pair<Parameter, double>>{{Parameter::ContractedPoints, 9000}, {Parameter::FullResolution, 1}}}) {
        EXPECT_EQ(settingsFrom(false, given).skeleton.resolution.maxContractedPoints, 0u);
    }
    // An inverted switch: keep_outliers on turns outlier detection off.
    EXPECT_FALSE(settingsFrom(false, {{Parameter::OutlierDetection, 1}}).skeleton.contraction.outliers.detect);
}

}  // namespace
}  // namespace pcskeleton
