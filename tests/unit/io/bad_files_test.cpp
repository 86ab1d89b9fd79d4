// The catalogue of malformed files in tests/data/bad_inputs (from the reliability probe
// and from fuzzing): every reader refuses each with a reason, or reads it right.
#include <pcskeleton/io/point_cloud_io.h>
#include <pcskeleton/io/skeleton_io.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

using namespace pcskeleton;

namespace {

const std::string kDirectory = PCSKELETON_BAD_INPUTS_DIR;

template <typename Read>
std::string errorOf(Read read) {
    try {
        read();
    } catch (const InvalidInput& e) {
        return e.what();
    }
    return "";
}

std::string pointsError(const std::string& name) {
    return errorOf([&] { readPointCloud(kDirectory + "/" + name); });
}
std::string skeletonError(const std::string& name) {
    return errorOf([&] { readSkeleton(kDirectory + "/" + name); });
}

}  // namespace

TEST(BadFiles, EachIsRefusedWithItsReason) {
    const std::vector<std::pair<std::string, std::string>> points = {
        {"empty.ply", "not a PLY file"},
        {"obj_vertex_garbage.obj", "line 2: a vertex (v) needs three numbers"},
        {"off_huge_count.off", "ends at vertex 1 of 99999999999999"},
        {"ply_binary_list_length_garbage.ply", "list 'extra' claims 255 items"},
        {"ply_element_without_properties.ply", "no property"},
        {"ply_no_end_header.ply", "without 'end_header'"},
        {"ply_no_xyz.ply", "no x, y and z"},
        {"ply_truncated_binary.ply", "declares 100 records"},
        {"ply_unknown_type.ply", "line 4: unknown property type"},
        {"ply_vertex_count_2pow31.ply", "declares 2147483648 records"},
        {"ply_vertex_count_2pow32.ply", "declares 4294967296 records"},
        {"ply_vertex_count_missing.ply", "line 3"},
        {"xyz_words.xyz", "line 2"},
    };
    for (const auto& [name, reason] : points) {
        EXPECT_NE(pointsError(name).find(reason), std::string::npos) << name << ": " << pointsError(name);
    }
    const std::vector<std::pair<std::string, std::string>> skeletons = {
        {"cg_counts_disagree.cg", "declares 3 vertices"},
        {"skeleton_edge_out_of_range.obj", "refers to vertex 99999999"},
        {"skeleton_edge_int_min.obj", "'-2147483648' is not a vertex index"},
        {"ply_binary_list_length_garbage.ply", "claims 255 items"},
    };
    for (const auto& [name, reason] : skeletons) {
        EXPECT_NE(skeletonError(name).find(reason), std::string::npos) << name << ": " << skeletonError(name);
    }
}

// Faces are not read for points or skeletons: what is wrong in them does not matter.
TEST(BadFiles, FacesAreNotRead) {
    EXPECT_EQ(readPointCloud(kDirectory + "/obj_face_index_out_of_range.obj").size(), 4u);
    EXPECT_EQ(readPointCloud(kDirectory + "/obj_face_index_int_min.obj").size(), 4u);
    EXPECT_EQ(readPointCloud(kDirectory + "/ply_face_list_negative_length.ply").size(), 3u);
    EXPECT_EQ(readSkeleton(kDirectory + "/ply_face_list_negative_length.ply").nodeCount(), 3u);
}

// vcglib read big-endian doubles without swapping them.
TEST(BadFiles, BigEndianDoublesAreSwapped) {
    const PointList points = readPointCloud(kDirectory + "/ply_big_endian_double.ply");
    EXPECT_EQ(points, (PointList{Point(0.5, 0, 0), Point(0, 1.25, 0), Point(0, 0, 2), Point(3, -1, 1e3)}));
}

// Every input that ever crashed a reader under fuzzing: read, or refused with a reason.
TEST(BadFiles, EveryFuzzFindIsReadOrRefused) {
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(kDirectory + "/fuzz_found")) {
        const std::string path = entry.path().string();
        ++files;
        for (bool asSkeleton : {false, true}) {
            try {
                if (asSkeleton) readSkeleton(path);
                else readPointCloud(path);
            } catch (const InvalidInput& e) {
                EXPECT_NE(std::string(e.what()).find("Cannot read"), std::string::npos) << path << ": " << e.what();
            }
        }
    }
    EXPECT_GT(files, 0);
}
