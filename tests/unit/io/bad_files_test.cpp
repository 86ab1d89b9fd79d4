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
    struct Case {
        const char* file;
        bool asSkeleton;  // read with readSkeleton, else readPointCloud
        const char* reason;
    };
    const Case cases[] = {
        {"empty.ply", false, "not a PLY file"},
        {"obj_vertex_garbage.obj", false, "line 2: a vertex (v) needs three numbers"},
        {"off_huge_count.off", false, "ends at vertex 1 of 99999999999999"},
        {"ply_binary_list_length_garbage.ply", false, "list 'extra' claims 255 items"},
        {"ply_element_without_properties.ply", false, "no property"},
        {"ply_no_end_header.ply", false, "without 'end_header'"},
        {"ply_no_xyz.ply", false, "no x, y and z"},
        {"ply_truncated_binary.ply", false, "declares 100 records"},
        {"ply_unknown_type.ply", false, "line 4: unknown property type"},
        {"ply_vertex_count_2pow31.ply", false, "declares 2147483648 records"},
        {"ply_vertex_count_2pow32.ply", false, "declares 4294967296 records"},
        {"ply_vertex_count_missing.ply", false, "line 3"},
        {"xyz_words.xyz", false, "line 2"},
        {"cg_counts_disagree.cg", true, "declares 3 vertices"},
        {"skeleton_edge_out_of_range.obj", true, "refers to vertex 99999999"},
        {"skeleton_edge_int_min.obj", true, "'-2147483648' is not a vertex index"},
        {"ply_binary_list_length_garbage.ply", true, "claims 255 items"},
        {"ply_ascii_record_longer_than_header.ply", false, "(line 8): the line holds more values than the header"},
        {"ply_ascii_record_shorter_than_header.ply", false, "(line 9): the line holds fewer values than the header"},
        {"ply_ascii_more_records_than_declared.ply", false, "line 12: the file goes on after the last record"},
        {"skeleton_ply_edge_line_four_values.ply", true, "(line 14): the line holds more values"},
        {"xyz_decimal_commas.xyz", false, "line 1: the numbers are not all separated alike"},
        {"off_decimal_commas.off", false, "line 3: vertex 0 of 3 does not have three coordinates (decimal commas"},
        {"obj_decimal_commas.obj", false, "line 1: a vertex (v) needs three numbers (decimal commas"},
        {"skeleton_obj_radius_decimal_comma.obj", true, "line 1: the value after a vertex's coordinates"},
    };
    for (const Case& c : cases) {
        const std::string error = c.asSkeleton ? skeletonError(c.file) : pointsError(c.file);
        EXPECT_NE(error.find(c.reason), std::string::npos) << c.file << ": " << error;
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
