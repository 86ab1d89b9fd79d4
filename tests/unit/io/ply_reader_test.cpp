// The PLY reader: every type and byte order decoded right, and every lie a header can
// tell (counts, list lengths, types) refused before it is acted on.
#include "support/temp_dir.h"
#include <pcskeleton/io/ply_reader.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

using namespace pcskeleton;
using pcskeleton::testing::TempDir;
using pcskeleton::testing::writeText;

namespace {

// Reads the element "v" with properties a and b; returns the records or the error.
struct Result {
    std::vector<std::vector<double>> records;
    std::string error;
};

Result readAB(const std::string& path) {
    Result result;
    PlyElementReader reader{"v", {"a", "b"}, nullptr, [&](const double* v) {
                                result.records.push_back({v[0], v[1]});
                            }};
    try {
        InputFile file(path);
        readPly(file, {reader});
    } catch (const InvalidInput& e) {
        result.error = e.what();
    }
    return result;
}

template <typename T>
std::string bytesOf(T value, bool bigEndian) {
    std::string bytes(sizeof(T), '\0');
    std::memcpy(bytes.data(), &value, sizeof(T));
    if (bigEndian) std::reverse(bytes.begin(), bytes.end());
    return bytes;
}

}  // namespace

TEST(PlyReader, DecodesEveryTypeInBothByteOrders) {
    TempDir dir;
    for (bool big : {false, true}) {
        const std::string header = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
                                   " 1.0\nelement v 1\nproperty char c\nproperty uchar uc\nproperty short s\n"
                                   "property ushort us\nproperty int i\nproperty uint ui\nproperty float a\n"
                                   "property double b\nend_header\n";
        const std::string body = bytesOf<std::int8_t>(-5, big) + bytesOf<std::uint8_t>(250, big) +
                                 bytesOf<std::int16_t>(-300, big) + bytesOf<std::uint16_t>(60000, big) +
                                 bytesOf<std::int32_t>(-70000, big) + bytesOf<std::uint32_t>(4000000000u, big) +
                                 bytesOf<float>(1.5f, big) + bytesOf<double>(-2.25e10, big);
        writeText(dir.file("t.ply"), header + body);
        std::vector<double> got;
        PlyElementReader reader{"v", {"c", "uc", "s", "us", "i", "ui", "a", "b", "missing"}, nullptr,
                                [&](const double* v) { got.assign(v, v + 9); }};
        InputFile file(dir.file("t.ply"));
        readPly(file, {reader});
        ASSERT_EQ(got.size(), 9u) << big;
        EXPECT_EQ(std::vector<double>(got.begin(), got.end() - 1),
                  (std::vector<double>{-5, 250, -300, 60000, -70000, 4000000000.0, 1.5, -2.25e10}))
            << (big ? "big endian" : "little endian");
        EXPECT_TRUE(std::isnan(got[8]));
    }
}

TEST(PlyReader, AsciiWithListsAndSkippedElements) {
    TempDir dir;
    writeText(dir.file("a.ply"), "ply\r\nformat ascii 1.0\r\ncomment hi\r\nelement face 2\r\n"
                                 "property list uchar int idx\r\nelement v 2\r\nproperty float a\r\n"
                                 "property list uchar float l\r\nproperty int8 b\r\nend_header\r\n"
                                 "3 0 1 2\r\n0\r\n1.5 2 7 8 -3\r\n2.5 0 4\r\n");
    const Result r = readAB(dir.file("a.ply"));
    EXPECT_EQ(r.error, "");
    EXPECT_EQ(r.records, (std::vector<std::vector<double>>{{1.5, -3}, {2.5, 4}}));
}

TEST(PlyReader, RefusesWhatTheHeaderCannotMeanWithTheLine) {
    TempDir dir;
    const std::string start = "ply\nformat ascii 1.0\n";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"plx\n", "not a PLY file"},
        {start + "element v\nproperty float a\nend_header\n", "line 3"},
        {start + "element v -1\nproperty float a\nend_header\n", "not a number"},
        {start + "element v 18446744073709551617\nproperty float a\nend_header\n", "not a number"},
        {start + "property float a\nend_header\n", "before any element"},
        {start + "element v 1\nproperty float128 a\nend_header\n", "unknown property type"},
        {start + "element v 1\nproperty list float int a\nend_header\n", "integer type"},
        {start + "element v 1\nproperty float a\n", "without 'end_header'"},
        {"ply\nelement v 1\nproperty float a\nend_header\n1\n", "no 'format'"},
        {"ply\nformat binary_middle_endian 1.0\nend_header\n", "unknown format"},
        {start + "element v 1\nproperty float a\nmystery\nend_header\n", "unknown header keyword"},
    };
    for (const auto& [text, expected] : cases) {
        writeText(dir.file("h.ply"), text);
        const std::string error = readAB(dir.file("h.ply")).error;
        EXPECT_NE(error.find(expected), std::string::npos) << text << "\n-> " << error;
    }
}

TEST(PlyReader, CountsAndListLengthsAreCheckedAgainstTheFileSize) {
    TempDir dir;
    // 2^32 records of 8 bytes in a file of 16: refused before any allocation, with the offset.
    writeText(dir.file("c.ply"), "ply\nformat binary_little_endian 1.0\nelement v 4294967296\nproperty float a\n"
                                 "property float b\nend_header\n" + std::string(16, '\0'));
    EXPECT_NE(readAB(dir.file("c.ply")).error.find("declares 4294967296 records"), std::string::npos);
    // A list claiming 2^31 items.
    writeText(dir.file("l.ply"), "ply\nformat binary_little_endian 1.0\nelement v 1\nproperty list int float l\n"
                                 "property float a\nend_header\n" + bytesOf<std::int32_t>(0x7fffffff, false) +
                                     std::string(8, '\0'));
    EXPECT_NE(readAB(dir.file("l.ply")).error.find("claims 2147483647 items"), std::string::npos);
    // A negative list length.
    writeText(dir.file("n.ply"), "ply\nformat ascii 1.0\nelement v 1\nproperty list char float l\nend_header\n-3 1 2 3\n");
    EXPECT_NE(readAB(dir.file("n.ply")).error.find("negative length"), std::string::npos);
    // An element with records and no property would be read for ever.
    writeText(dir.file("e.ply"), "ply\nformat ascii 1.0\nelement e 999999999999\nelement v 0\nproperty float a\nend_header\n");
    EXPECT_NE(readAB(dir.file("e.ply")).error.find("no property"), std::string::npos);
    // Data ends early: the record and the byte offset are named.
    writeText(dir.file("t.ply"), "ply\nformat binary_little_endian 1.0\nelement v 2\nproperty list uchar float l\n"
                                 "end_header\n" + std::string(1, '\x01') + std::string(4, '\0') + std::string(1, '\x03') +
                                     std::string(4, '\0'));
    EXPECT_NE(readAB(dir.file("t.ply")).error.find("record 1 of element 'v'"), std::string::npos);
}

TEST(PlyReader, AsciiValuesMustBeNumbersInRange) {
    TempDir dir;
    const std::string header = "ply\nformat ascii 1.0\nelement v 1\nproperty uchar a\nproperty float b\nend_header\n";
    writeText(dir.file("a.ply"), header + "256 1\n");
    EXPECT_NE(readAB(dir.file("a.ply")).error.find("out of range"), std::string::npos);
    writeText(dir.file("b.ply"), header + "1 one\n");
    EXPECT_NE(readAB(dir.file("b.ply")).error.find("line 7"), std::string::npos);
    writeText(dir.file("c.ply"), header + "1.5 1\n");
    EXPECT_NE(readAB(dir.file("c.ply")).error.find("not an integer"), std::string::npos);
}

TEST(InputFile, RefusesDirectoriesAndMissingFiles) {
    TempDir dir;
    try {
        InputFile file(dir.path());
        FAIL() << "a directory was opened";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos);
    }
    EXPECT_THROW(InputFile(dir.file("none.ply")), InvalidInput);
}
