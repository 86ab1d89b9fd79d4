// Surface files: every format holds the mesh's vertices and triangles.
#include "support/temp_dir.h"
#include <pcskeleton/io/mesh_io.h>
#include <pcskeleton/io/point_cloud_io.h>

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

using namespace pcskeleton;
using pcskeleton::testing::TempDir;

namespace {

TriangleMesh tetrahedron() {
    TriangleMesh m;
    m.vertices = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1.5)};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
    return m;
}

std::string textOf(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

TEST(MeshFiles, EveryFormatHoldsTheVerticesAndTriangles) {
    TempDir dir;
    const TriangleMesh m = tetrahedron();
    for (const char* name : {"t.ply", "t.off", "t.obj"}) {
        writeTriangleMesh(m, dir.file(name));
        EXPECT_EQ(readPointCloud(dir.file(name)), m.vertices) << name;
    }
    EXPECT_EQ(textOf(dir.file("t.off")).substr(0, 10), "OFF\n4 4 0\n");
    EXPECT_NE(textOf(dir.file("t.obj")).find("f 1 3 2\nf 1 2 4\n"), std::string::npos);
    EXPECT_NE(textOf(dir.file("t.ply")).find("element face 4\nproperty list uchar int vertex_indices"), std::string::npos);
    EXPECT_THROW(writeTriangleMesh(m, dir.file("t.stl")), InvalidInput);
    EXPECT_THROW(writeTriangleMesh(m, dir.file("none/t.off")), InvalidInput);
}
