// The reading and writing primitives every reader and writer goes through: numbers read
// the same in every locale and at the edges of a double's range, decimal commas told
// apart from separators, output paths checked before any work, temporaries of killed runs
// cleaned up.
#include <pcskeleton/io/input_file.h>
#include "support/temp_dir.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <clocale>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>

using namespace pcskeleton;
using pcskeleton::testing::TempDir;

namespace {

double numberOf(const std::string& text) {
    double value = -123;
    EXPECT_TRUE(parseNumber(text.data(), text.data() + text.size(), value)) << text;
    return value;
}

bool isNumber(const std::string& text) {
    double value = 0;
    return parseNumber(text.data(), text.data() + text.size(), value);
}

std::string writableError(const std::string& path) {
    try {
        checkWritable(path);
    } catch (const InvalidInput& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(ParseNumber, ReadsPlainExtremeAndSpecialNumbers) {
    EXPECT_EQ(numberOf("1.5"), 1.5);
    EXPECT_EQ(numberOf("+2"), 2.0);
    EXPECT_EQ(numberOf("-1e-3"), -1e-3);
    EXPECT_EQ(numberOf("4.9e-324"), 4.9e-324);  // the smallest subnormal
    EXPECT_EQ(numberOf("1e400"), std::numeric_limits<double>::infinity());
    EXPECT_EQ(numberOf("-1e400"), -std::numeric_limits<double>::infinity());
    EXPECT_EQ(numberOf("1e-400"), 0.0);
    EXPECT_TRUE(std::isnan(numberOf("nan")));
    EXPECT_TRUE(std::isinf(numberOf("inf")));
    EXPECT_FALSE(isNumber("1,5"));
    EXPECT_FALSE(isNumber("1.5abc"));
    EXPECT_FALSE(isNumber(""));
    EXPECT_FALSE(isNumber("+"));
}

// MeshLab runs in the user's locale; strtod there takes "1.5" for 1 in German.
TEST(ParseNumber, IsTheSameInALocaleWithADecimalComma) {
    const char* previous = std::setlocale(LC_NUMERIC, nullptr);
    const std::string saved = previous ? previous : "C";
    // A German locale, made for the test when the machine has none (Debian's locales package).
    const TempDir locales;
    if (!std::setlocale(LC_NUMERIC, "de_DE.UTF-8")) {
        const std::string make = "localedef -i de_DE -f UTF-8 " + locales.file("de_DE.UTF-8") + " >/dev/null 2>&1";
        if (std::system(make.c_str()) != -1) ::setenv("LOCPATH", locales.path().c_str(), 1);
    }
    const bool switched = std::setlocale(LC_NUMERIC, "de_DE.UTF-8") != nullptr;
    ::unsetenv("LOCPATH");
    if (!switched) GTEST_SKIP() << "no German locale, and localedef could not make one";
    EXPECT_EQ(std::string(std::localeconv()->decimal_point), ",");
    EXPECT_EQ(numberOf("1.5"), 1.5);
    EXPECT_FALSE(isNumber("1,5"));
    std::setlocale(LC_NUMERIC, saved.c_str());
}

TEST(ReadNumber, CommasSeparateOnlyWhereAllowed) {
    const std::string line = "1.5,2.5, 3.5";
    const char* cursor = line.c_str();
    double x = 0, y = 0, z = 0;
    EXPECT_TRUE(readNumber(cursor, x, NumberSeparators::BlanksOrCommas));
    EXPECT_TRUE(readNumber(cursor, y, NumberSeparators::BlanksOrCommas));
    EXPECT_TRUE(readNumber(cursor, z, NumberSeparators::BlanksOrCommas));
    EXPECT_EQ(x + y + z, 7.5);
    cursor = line.c_str();
    EXPECT_FALSE(readNumber(cursor, x));  // "1.5,2.5," is not a number
}

TEST(MixesCommasAndBlanks, TellsDecimalCommasFromCommaSeparatedValues) {
    EXPECT_TRUE(mixesCommasAndBlanks("1,5 2,5 3,5"));
    EXPECT_TRUE(mixesCommasAndBlanks("1,5\t2,5\t3,5"));
    EXPECT_FALSE(mixesCommasAndBlanks("1.5,2.5,3.5"));
    EXPECT_FALSE(mixesCommasAndBlanks("1.5, 2.5, 3.5"));
    EXPECT_FALSE(mixesCommasAndBlanks("1.5 2.5 3.5"));
    EXPECT_FALSE(mixesCommasAndBlanks("  1.5 2.5 3.5  "));
    EXPECT_TRUE(mixesCommasAndBlanks("0,5, 1,5, 2,5"));  // decimal commas in comma-separated values
    EXPECT_FALSE(mixesCommasAndBlanks("1.5"));
}

TEST(CheckWritable, RefusesEveryPathThatCannotBeWrittenWithItsReason) {
    const TempDir dir;
    EXPECT_EQ(writableError(dir.file("fine.ply")), "");
    EXPECT_FALSE(std::filesystem::exists(dir.file("fine.ply")));  // the check leaves nothing behind
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 0);

    EXPECT_NE(writableError(dir.file(std::string(300, 'a') + ".ply")).find("304 bytes long"), std::string::npos);
    EXPECT_NE(writableError(dir.file("missing/x.ply")).find("does not exist"), std::string::npos);
    EXPECT_NE(writableError(dir.path()).find("is a directory"), std::string::npos);
    ASSERT_EQ(::symlink("loop", dir.file("loop").c_str()), 0);
    EXPECT_NE(writableError(dir.file("loop")).find("symbolic links"), std::string::npos);
    EXPECT_NE(writableError(dir.file("loop/x.ply")).find("symbolic links"), std::string::npos);
    EXPECT_NE(writableError("").find("no file name"), std::string::npos);
}

// Root writes to any folder: as root the check runs in a child that became nobody.
TEST(CheckWritableDeathTest, RefusesAFolderWithoutPermission) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    const TempDir dir;
    ::chmod(dir.path().c_str(), 0755);
    const std::string locked = dir.file("locked");
    ASSERT_EQ(::mkdir(locked.c_str(), 0500), 0);
    const auto check = [&] {
        if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) std::_Exit(3);
        const std::string error = writableError(locked + "/x.ply");
        std::_Exit(error.find("Permission denied") != std::string::npos ? 42 : 1);
    };
    EXPECT_EXIT(check(), ::testing::ExitedWithCode(42), "");
    ::chmod(locked.c_str(), 0700);
}

TEST(WriteFileAtomically, NameLongerThanItsTemporaryCouldBeIsWritten) {
    const TempDir dir;
    const std::string path = dir.file(std::string(250, 'b') + ".txt");  // 254 bytes: fits, its temporary would not
    writeFileAtomically(path, [](const std::string& temporary) { pcskeleton::testing::writeText(temporary, "x"); });
    EXPECT_TRUE(std::filesystem::exists(path));
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);
}

TEST(WriteFileAtomically, RemovesTheTemporariesOfKilledRunsOnly) {
    const TempDir dir;
    const pid_t child = fork();
    if (child == 0) _exit(0);
    ASSERT_GT(child, 0);
    waitpid(child, nullptr, 0);  // a process that is gone
    const std::string stale = dir.file("out.ply.partial-" + std::to_string(child) + "-Ab12Cd");
    const std::string live = dir.file("out.ply.partial-" + std::to_string(getppid()) + "-Ef34Gh");
    const std::string other = dir.file("other.ply.partial-" + std::to_string(child) + "-Ij56Kl");
    for (const std::string& file : {stale, live, other}) pcskeleton::testing::writeText(file, "partial");

    writeFileAtomically(dir.file("out.ply"), [](const std::string& temporary) {
        pcskeleton::testing::writeText(temporary, "done");
    });
    EXPECT_FALSE(std::filesystem::exists(stale));
    EXPECT_TRUE(std::filesystem::exists(live));   // its process still runs
    EXPECT_TRUE(std::filesystem::exists(other));  // another file's, left to its own next write
    EXPECT_TRUE(std::filesystem::exists(dir.file("out.ply")));
}
