// Point-set files: every format is read as written, and unreadable files say why.
#include "support/sampled_shapes.h"
#include <pcskeleton/io/point_cloud_io.h>

#include "support/temp_dir.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace pcskeleton;
using pcskeleton::testing::TempDir;
using pcskeleton::testing::writeText;

namespace {

std::string errorReading(const std::string& path) {
    try {
        readPointCloud(path);
    } catch (const InvalidInput& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(PointFiles, BinaryPlyXyzOffAndObjAreRead) {
    TempDir dir;
    const PointList cloud = shapes::sphere(200, 1.0);
    writePointCloud(cloud, dir.file("c.ply"));  // binary
    EXPECT_EQ(readPointCloud(dir.file("c.ply")), cloud);
    writePointCloud(cloud, dir.file("c.xyz"));
    const PointList xyz = readPointCloud(dir.file("c.xyz"));
    ASSERT_EQ(xyz.size(), cloud.size());
    for (std::size_t i = 0; i < cloud.size(); ++i) EXPECT_LT((xyz[i] - cloud[i]).norm(), 1e-12);

    // The paper's own files: two counts, normals after the coordinates, faces ignored.
    writeText(dir.file("n.off"), "NOFF\n3 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n");
    EXPECT_EQ(readPointCloud(dir.file("n.off")).size(), 3u);
    writeText(dir.file("m.off"), "OFF\n# comment\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n2 0 0\n");
    EXPECT_EQ(readPointCloud(dir.file("m.off"))[3], Point(0, 0, 1));
    writeText(dir.file("m.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\n");
    EXPECT_EQ(readPointCloud(dir.file("m.obj")).size(), 4u);
    writeText(dir.file("c.txt"), "# x y z\n1, 2, 3\n4 5 6 255 0 0\n");
    EXPECT_EQ(readPointCloud(dir.file("c.txt"))[1], Point(4, 5, 6));
}

TEST(PointFiles, UnreadableFilesSayWhy) {
    TempDir dir;
    EXPECT_NE(errorReading(dir.file("none.ply")).find("cannot be opened"), std::string::npos);
    EXPECT_NE(errorReading(dir.file("c.las")).find("unknown extension"), std::string::npos);
    writeText(dir.file("short.off"), "OFF\n5 0 0\n0 0 0\n");
    EXPECT_NE(errorReading(dir.file("short.off")).find("vertex 1 of 5"), std::string::npos);
    writeText(dir.file("words.xyz"), "1 2 3\nhello world\n");
    EXPECT_NE(errorReading(dir.file("words.xyz")).find("line 2"), std::string::npos);
    writeText(dir.file("broken.ply"), "ply\nformat ascii 1.0\nelement vertex 3\nend_header\n");
    EXPECT_NE(errorReading(dir.file("broken.ply")), "");
}
