// The files a batch's arguments name, and the names of their outputs: folders give their
// point files, globs their matches, each file once; inputs of one name get distinct names.
#include <pcskeleton/io/batch_files.h>
#include <pcskeleton/core/errors.h>
#include "support/temp_dir.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

using namespace pcskeleton;
using pcskeleton::testing::TempDir;
using pcskeleton::testing::writeText;

TEST(BatchFiles, AFolderGivesItsPointFilesSortedAndNotItsSubfolders) {
    TempDir dir;
    std::filesystem::create_directories(dir.file("scans/deeper"));
    for (const char* name : {"scans/b.ply", "scans/a.xyz", "scans/notes.md", "scans/deeper/c.ply"}) writeText(dir.file(name), "0 0 0\n");
    EXPECT_EQ(expandInputs({dir.file("scans")}),
              (std::vector<std::string>{dir.file("scans") + "/a.xyz", dir.file("scans") + "/b.ply"}));
}

TEST(BatchFiles, AGlobGivesItsMatchesAndEachFileComesOnce) {
    TempDir dir;
    for (const char* name : {"s1.ply", "s2.ply", "t.ply"}) writeText(dir.file(name), "0 0 0\n");
    EXPECT_EQ(expandInputs({dir.file("s*.ply"), dir.file("s1.ply"), dir.file("t.ply")}),
              (std::vector<std::string>{dir.file("s1.ply"), dir.file("s2.ply"), dir.file("t.ply")}));
}

TEST(BatchFiles, AMissingFileIsKeptForItsRunToReport) {
    EXPECT_EQ(expandInputs({"/no/such/scan.ply"}), (std::vector<std::string>{"/no/such/scan.ply"}));
}

TEST(BatchFiles, AnEmptyGlobOrFolderIsRefused) {
    TempDir dir;
    EXPECT_THROW(expandInputs({dir.file("*.ply")}), InvalidInput);
    EXPECT_THROW(expandInputs({dir.path()}), InvalidInput);
}

TEST(BatchFiles, InputsOfOneNameAreToldApartByFolderThenExtension) {
    EXPECT_EQ(outputStems({"/d/a/scan.ply", "/d/b/scan.ply", "/d/c/other.ply"}),
              (std::vector<std::string>{"a_scan", "b_scan", "other"}));
    EXPECT_EQ(outputStems({"/d/a/scan.ply", "/d/a/scan.xyz"}), (std::vector<std::string>{"scan_ply", "scan_xyz"}));
    EXPECT_EQ(outputStems({"/x/a/s.ply", "/y/a/s.ply"}), (std::vector<std::string>{"x_a_s", "y_a_s"}));
    // A told-apart name meeting another input's own name is numbered.
    EXPECT_EQ(outputStems({"/d/a_scan.ply", "/d/a/scan.ply", "/d/b/scan.ply"}),
              (std::vector<std::string>{"a_scan", "a_scan_2", "b_scan"}));
}

TEST(BatchFiles, PatternsTakeTheStem) {
    EXPECT_EQ(fromPattern("{stem}_skeleton.ply", "corn"), "corn_skeleton.ply");
    EXPECT_EQ(fromPattern("{stem}/{stem}.csv", "a"), "a/a.csv");
    EXPECT_EQ(fromPattern("fixed.ply", "a"), "fixed.ply");
}
