// The library's binary PLY: point sets and surfaces read back exactly (doubles, triangles),
// and a path that cannot be written refused with InvalidInput, leaving nothing behind.
#include <pcskeleton/io/ply_writer.h>
#include <pcskeleton/io/point_cloud_io.h>
#include <pcskeleton/core/errors.h>
#include "support/temp_dir.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

using namespace pcskeleton;
using pcskeleton::testing::TempDir;

namespace {

std::string header(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return text.substr(0, text.find("end_header\n") + 11);
}

}  // namespace

TEST(PlyWriter, PointsReadBackBitForBit) {
    const TempDir dir;
    const PointList points = {Point(0.1, -2.5e-300, 3), Point(1e300, 0, -0.0), Point(1.0 / 3, 2.0 / 3, 1)};
    const std::string path = dir.file("points.ply");
    writeBinaryPly(path, points);
    const std::string h = header(path);
    EXPECT_NE(h.find("format binary_little_endian 1.0"), std::string::npos) << h;
    EXPECT_NE(h.find("element vertex 3"), std::string::npos) << h;
    EXPECT_EQ(h.find("element face"), std::string::npos) << h;
    const PointList back = readPointCloud(path);
    ASSERT_EQ(back.size(), points.size());
    for (std::size_t i = 0; i < points.size(); ++i) EXPECT_EQ(back[i], points[i]) << i;
}

TEST(PlyWriter, TrianglesAreAFaceListOfTheirSize) {
    const TempDir dir;
    const PointList vertices = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)};
    const std::vector<std::array<int, 3>> triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
    const std::string path = dir.file("tetrahedron.ply");
    writeBinaryPly(path, vertices, &triangles);
    const std::string h = header(path);
    EXPECT_NE(h.find("element face 4"), std::string::npos) << h;
    EXPECT_NE(h.find("property list uchar int vertex_indices"), std::string::npos) << h;
    // Header, 4 vertices of 3 doubles, 4 faces of one count byte and 3 ints.
    EXPECT_EQ(std::filesystem::file_size(path), h.size() + 4 * 24 + 4 * 13);
    const PointList back = readPointCloud(path);  // a mesh's vertices are its points
    ASSERT_EQ(back.size(), vertices.size());
    for (std::size_t i = 0; i < vertices.size(); ++i) EXPECT_EQ(back[i], vertices[i]);
}

TEST(PlyWriter, AnUnwritablePathIsRefusedAndLeavesNothing) {
    const TempDir dir;
    const std::string path = dir.file("no_such_folder/points.ply");
    EXPECT_THROW(writeBinaryPly(path, {Point(0, 0, 0)}), InvalidInput);
    EXPECT_FALSE(std::filesystem::exists(dir.file("no_such_folder")));
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}
