// The parameter table: every parameter described once, found by its name and its former
// name, its words the library's, "automatic" said where 0 means it.
#include <pcskeleton/core/parameter_table.h>

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace pcskeleton {
namespace {

TEST(ParameterTable, EveryParameterHasOneEntryWithUniqueNames) {
    std::set<std::string> names, meshlabNames;
    for (const ParameterInfo& p : parameterTable()) {
        EXPECT_TRUE(names.insert(p.name).second) << p.name;
        if (p.meshlabName) EXPECT_TRUE(meshlabNames.insert(p.meshlabName).second) << p.meshlabName;
        EXPECT_EQ(&parameterInfo(p.id), &p) << p.name;
        EXPECT_EQ(parameterNamed(p.name), &p) << p.name;
        EXPECT_FALSE(std::string(p.help).empty()) << p.name;
        EXPECT_EQ(libraryTerms().parameter(p.id), p.words) << p.name;
    }
    EXPECT_EQ(parameterNamed("radius"), &parameterInfo(Parameter::NodeSpacing)) << "the former name still works";
    EXPECT_EQ(parameterNamed("no_such_parameter"), nullptr);
}

TEST(ParameterTable, WhereZeroMeansAutomaticTheLabelSaysSo) {
    for (Parameter id : {Parameter::NeighbourCount, Parameter::InitialContractionWeight, Parameter::MemoryLimit}) {
        EXPECT_NE(std::string(parameterInfo(id).label).find("automatic"), std::string::npos) << parameterInfo(id).name;
    }
}

}  // namespace
}  // namespace pcskeleton
