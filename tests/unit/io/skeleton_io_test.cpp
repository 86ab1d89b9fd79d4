// Skeleton files: what is written is read back as the same graph, and unreadable files
// give a clear error.
#include <pcskeleton/io/skeleton_io.h>

#include "support/temp_dir.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace pcskeleton;
using pcskeleton::testing::TempDir;
using pcskeleton::testing::writeText;

namespace {

// A graph with a cycle, a junction, a tip and an isolated node.
SkeletonGraph sampleSkeleton() {
    SkeletonGraph s;
    s.nodes = {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0.5), Point(2, 0, 0), Point(5, 5, 5)};
    s.radii = {0.1, 0.2, 0.3, 0.4, 0.05, 0.25};
    s.edges = {{0, 1}, {0, 3}, {1, 2}, {1, 4}, {2, 3}};
    return s;
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

TEST(SkeletonFiles, PlyKeepsWhichBonesAreInferred) {
    TempDir dir;
    SkeletonGraph s = sampleSkeleton();
    s.inferred = {{1, 4}};
    writeSkeleton(s, dir.file("s.ply"));
    EXPECT_EQ(readSkeleton(dir.file("s.ply")).inferred, s.inferred);
    // A PLY without the property (MeshLab's export, other tools): no bone is inferred.
    writeText(dir.file("plain.ply"),
              "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
              "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n0 0 0\n1 0 0\n0 1\n");
    const SkeletonGraph plain = readSkeleton(dir.file("plain.ply"));
    EXPECT_EQ(plain.edges.size(), 1u);
    EXPECT_TRUE(plain.inferred.empty());
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

TEST(SkeletonFiles, BinaryPlyAndMeshLabsQualityRadius) {
    TempDir dir;
    // MeshLab's own PLY export of a skeleton layer keeps the radius in quality only.
    writeText(dir.file("q.ply"), "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
                                 "property float z\nproperty float quality\nelement edge 1\nproperty int vertex1\n"
                                 "property int vertex2\nend_header\n0 0 0 0.5\n1 0 0 0.25\n0 1\n");
    const SkeletonGraph q = readSkeleton(dir.file("q.ply"));
    EXPECT_EQ(q.radii, (std::vector<double>{0.5, 0.25}));
    EXPECT_EQ(q.edges, (std::vector<Edge>{{0, 1}}));
}

TEST(SkeletonFiles, EdgesAndCountsAreChecked) {
    TempDir dir;
    writeText(dir.file("e.ply"), "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
                                 "property float z\nelement edge 1\nproperty int vertex1\nproperty int vertex2\n"
                                 "end_header\n0 0 0\n1 0 0\n0 2\n");
    EXPECT_THROW(readSkeleton(dir.file("e.ply")), InvalidInput);
    writeText(dir.file("c.cg"), "# D:3 NV:3 NE:1\nv 0 0 0\nv 1 0 0\ne 1 2\n");
    EXPECT_THROW(readSkeleton(dir.file("c.cg")), InvalidInput);
    // A relative index counts back from the vertices read so far, not from the file's end.
    writeText(dir.file("r.obj"), "v 0 0 0\nv 1 0 0\nl 1 -1\nv 2 0 0\nl 2 3\n");
    EXPECT_EQ(readSkeleton(dir.file("r.obj")).edges, (std::vector<Edge>{{0, 1}, {1, 2}}));
}

TEST(SkeletonFiles, WritingGoesThroughATemporaryThatDoesNotStay) {
    TempDir dir;
    writeText(dir.file("s.obj"), "old");
    writeSkeleton(sampleSkeleton(), dir.file("s.obj"));
    EXPECT_EQ(readSkeleton(dir.file("s.obj")).nodeCount(), 6u);
    EXPECT_THROW(writeSkeleton(sampleSkeleton(), dir.file("missing/s.obj")), InvalidInput);
    const auto entries = std::distance(std::filesystem::directory_iterator(dir.path()), {});
    EXPECT_EQ(entries, 1);
}

