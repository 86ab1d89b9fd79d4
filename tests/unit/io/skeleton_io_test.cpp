// Skeleton and point-set files: what is written is read back as the same graph, and
// unreadable files give a clear error.
#include "support/sampled_shapes.h"
#include <pcskeleton/io/point_cloud_io.h>
#include <pcskeleton/io/skeleton_io.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <unistd.h>

using namespace pcskeleton;

namespace {

class TempDir {
public:
    TempDir() {
        char pattern[] = "/tmp/pcskeleton_io_XXXXXX";
        path_ = mkdtemp(pattern);
    }
    ~TempDir() { std::system(("rm -rf '" + path_ + "'").c_str()); }
    std::string file(const std::string& name) const { return path_ + "/" + name; }

private:
    std::string path_;
};

void writeText(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// A graph with a cycle, a junction, a tip and an isolated node.
SkeletonGraph sampleSkeleton() {
    SkeletonGraph s;
    s.nodes = {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0.5), Point(2, 0, 0), Point(5, 5, 5)};
    s.radii = {0.1, 0.2, 0.3, 0.4, 0.05, 0.25};
    s.edges = {{0, 1}, {0, 3}, {1, 2}, {1, 4}, {2, 3}};
    return s;
}

std::string errorReading(const std::string& path) {
    try {
        readPointCloud(path);
    } catch (const InvalidInput& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(SkeletonFiles, PlyKeepsNodesEdgesAndRadii) {
    TempDir dir;
    const SkeletonGraph s = sampleSkeleton();
    writeSkeleton(s, dir.file("s.ply"));
    const SkeletonGraph back = readSkeleton(dir.file("s.ply"));
    EXPECT_EQ(back.edges, s.edges);
    ASSERT_EQ(back.nodes.size(), s.nodes.size());
    for (std::size_t n = 0; n < s.nodes.size(); ++n) {
        EXPECT_EQ(back.nodes[n], s.nodes[n]);
        EXPECT_NEAR(back.radii[n], s.radii[n], 1e-6);
    }
    const SkeletonTopology t = analyseTopology(back);
    EXPECT_EQ(t.cycles, 1);
    EXPECT_EQ(t.isolated, 1);
}

TEST(SkeletonFiles, ObjAndCgKeepTheGraph) {
    TempDir dir;
    const SkeletonGraph s = sampleSkeleton();
    for (const char* name : {"s.obj", "s.cg"}) {
        writeSkeleton(s, dir.file(name));
        const SkeletonGraph back = readSkeleton(dir.file(name));
        EXPECT_EQ(back.edges, s.edges) << name;
        ASSERT_EQ(back.nodes.size(), s.nodes.size()) << name;
        for (std::size_t n = 0; n < s.nodes.size(); ++n) EXPECT_EQ(back.nodes[n], s.nodes[n]) << name;
    }
    std::ifstream cg(dir.file("s.cg"));
    std::string header;
    std::getline(cg, header);
    EXPECT_EQ(header, "# D:3 NV:6 NE:5");
}

TEST(SkeletonFiles, ObjPolylinesBecomeEdges) {
    TempDir dir;
    writeText(dir.file("p.obj"), "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nl 1 2 3 4\nl -1 1\n");
    const SkeletonGraph s = readSkeleton(dir.file("p.obj"));
    EXPECT_EQ(s.edges, (std::vector<Edge>{{0, 1}, {0, 3}, {1, 2}, {2, 3}}));
}

TEST(SkeletonFiles, BadSkeletonFilesAreRefused) {
    TempDir dir;
    writeText(dir.file("bad.obj"), "v 0 0 0\nl 1 7\n");
    EXPECT_THROW(readSkeleton(dir.file("bad.obj")), InvalidInput);
    EXPECT_THROW(readSkeleton(dir.file("missing.ply")), InvalidInput);
    EXPECT_THROW(readSkeleton(dir.file("s.swc")), InvalidInput);
    EXPECT_THROW(writeSkeleton(sampleSkeleton(), dir.file("s.txt")), InvalidInput);
    EXPECT_THROW(writeSkeleton(sampleSkeleton(), "/nonexistent-dir/s.cg"), InvalidInput);
}

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
