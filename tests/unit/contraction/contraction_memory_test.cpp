// The memory estimate grows with the work, and work larger than the limit given is refused
// before it starts, naming what it needs and how many contracted points would fit.
#include <pcskeleton/contraction/contraction_memory.h>
#include <pcskeleton/core/errors.h>

#include <gtest/gtest.h>

#include <string>

using namespace pcskeleton;

TEST(ContractionMemory, TheEstimateGrowsWithThePointsContractedAndCarried) {
    EXPECT_LT(estimatedPeakBytes(10000, 0), estimatedPeakBytes(20000, 0));
    EXPECT_LT(estimatedPeakBytes(1000000, 10000), estimatedPeakBytes(1000000, 20000));
    EXPECT_LT(estimatedPeakBytes(1000000, 20000), estimatedPeakBytes(2000000, 20000));
    // A cap larger than the cloud contracts the whole cloud.
    EXPECT_DOUBLE_EQ(estimatedPeakBytes(5000, 20000), estimatedPeakBytes(5000, 0));
    // Contracting costs far more per point than carrying.
    EXPECT_GT(estimatedPeakBytes(100000, 0), 5 * estimatedPeakBytes(100000, 10000));
}

TEST(ContractionMemory, WorkWithinTheLimitIsNotRefused) {
    EXPECT_NO_THROW(refuseWorkLargerThanMemory(1000, 0, 0));  // no limit of the user's
    EXPECT_NO_THROW(refuseWorkLargerThanMemory(1000, 0, 2 * estimatedPeakBytes(1000, 0)));
}

TEST(ContractionMemory, WorkBeyondTheLimitIsRefusedWithWhatWouldFit) {
    const double limit = 0.5 * estimatedPeakBytes(100000, 0);
    try {
        refuseWorkLargerThanMemory(100000, 0, limit);
        FAIL() << "no refusal";
    } catch (const InvalidInput& e) {
        const std::string text = e.what();
        EXPECT_NE(text.find("100000 points, all 100000 of them contracted"), std::string::npos) << text;
        EXPECT_NE(text.find("allowed"), std::string::npos) << text;
        EXPECT_NE(text.find("contracted points would fit"), std::string::npos) << text;
        ASSERT_EQ(e.problem().remedies.size(), 1u);
        EXPECT_EQ(e.problem().remedies[0].parameter, Parameter::ContractedPoints);
    }
}

TEST(ContractionMemory, WhenNotEvenTheCarriedPointsFitItSaysToSplitTheScan) {
    try {
        refuseWorkLargerThanMemory(10000000, 20000, 1e6);
        FAIL() << "no refusal";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("split the scan"), std::string::npos) << e.what();
        EXPECT_TRUE(e.problem().remedies.empty());
    }
}
