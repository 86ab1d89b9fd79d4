#include "pcskeleton/io/point_cloud_io.h"

#include "pcskeleton/io/input_file.h"
#include "pcskeleton/io/ply_reader.h"
#include "pcskeleton/io/ply_writer.h"

#include <algorithm>
#include <cmath>
#include <ostream>

namespace pcskeleton {

namespace {

PointList readPlyPoints(InputFile& file) {
    PointList points;
    bool sawVertices = false;
    PlyElementReader vertices{"vertex", {"x", "y", "z"}, nullptr, nullptr};
    vertices.begin = [&](const PlyElement& element) {
        if (!element.has("x") || !element.has("y") || !element.has("z")) {
            file.fail("the vertex element has no x, y and z properties.");
        }
        sawVertices = true;
        points.reserve(file.reservable(element.count, 3));
    };
    vertices.record = [&](const double* xyz) { points.emplace_back(xyz[0], xyz[1], xyz[2]); };
    readPly(file, {vertices});
    if (!sawVertices) file.fail("the file has no vertex element.");
    return points;
}

PointList readXyz(InputFile& file) {
    PointList points;
    std::string line;
    while (file.readLine(line)) {
        const auto first = line.find_first_not_of(" \t");
        if (first == std::string::npos || line[first] == '#') continue;
        if (mixesCommasAndBlanks(line)) {
            file.failAtLine("the numbers are not all separated alike (by commas, blanks, or both): decimal commas "
                            "('1,5') are not read; write numbers with a dot ('1.5').");
        }
        const char* cursor = line.c_str();
        Point p;
        constexpr NumberSeparators commas = NumberSeparators::BlanksOrCommas;
        if (!readNumber(cursor, p.x(), commas) || !readNumber(cursor, p.y(), commas) || !readNumber(cursor, p.z(), commas)) {
            file.failAtLine("a point line starts with three numbers (x y z).");
        }
        points.push_back(p);
    }
    return points;
}

// The vertices of an OFF file, read leniently: vcglib's reader rejects the two-count
// headers ("NOFF / 9471 0") of the paper's own files and degenerate faces, which a point
// cloud does not need anyway. Extra values per vertex (normals, colours) are ignored.
PointList readOffVertices(InputFile& file) {
    std::string line;
    auto nextLine = [&]() {
        while (file.readLine(line)) {
            line = line.substr(0, line.find('#'));
            if (line.find_first_not_of(" \t") != std::string::npos) return true;
        }
        return false;
    };
    if (!nextLine()) file.fail("the file is empty.");
    const auto keywordStart = line.find_first_not_of(" \t");
    const auto keywordEnd = std::min(line.find_first_of(" \t", keywordStart), line.size());
    const std::string keyword = line.substr(keywordStart, keywordEnd - keywordStart);
    if (keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0) {
        file.fail("an OFF file starts with OFF (or NOFF, COFF, ...).");
    }
    if (keyword.find('4') != std::string::npos || keyword.find('n') != std::string::npos) {
        file.fail("OFF files with other than three dimensions are not supported.");
    }
    const char* cursor = line.c_str() + keywordEnd;
    double count = -1;
    if (!readNumber(cursor, count)) {
        if (!nextLine()) file.fail("the vertex count is missing.");
        cursor = line.c_str();
        if (!readNumber(cursor, count)) file.failAtLine("the vertex count is missing.");
    }
    if (count < 0 || count != std::floor(count) || count > 1e18) {
        file.failAtLine("the vertex count is not a whole number of vertices.");
    }
    const std::uint64_t vertices = std::uint64_t(count);
    PointList points;
    points.reserve(file.reservable(vertices, 6));  // "0 0 0\n"
    for (std::uint64_t i = 0; i < vertices; ++i) {
        if (!nextLine()) {
            file.fail("the file ends at vertex " + std::to_string(i) + " of " + std::to_string(vertices) + ".");
        }
        cursor = line.c_str();
        Point p;
        if (!readNumber(cursor, p.x()) || !readNumber(cursor, p.y()) || !readNumber(cursor, p.z())) {
            file.failAtLine("vertex " + std::to_string(i) + " of " + std::to_string(vertices) +
                            " does not have three coordinates" + decimalCommaHint(line) + ".");
        }
        points.push_back(p);
    }
    return points;
}

// Only the v lines of an OBJ file. tinyobjloader (in Debian) was considered: it reads a
// malformed coordinate as 0 without a word and reports no line numbers, and a point
// cloud needs none of what it adds (faces, materials).
PointList readObjVertices(InputFile& file) {
    PointList points;
    std::string line;
    while (file.readLine(line)) {
        const char* cursor = line.c_str();
        while (*cursor == ' ' || *cursor == '\t') ++cursor;
        if (cursor[0] != 'v' || (cursor[1] != ' ' && cursor[1] != '\t')) continue;
        ++cursor;
        Point p;
        if (!readNumber(cursor, p.x()) || !readNumber(cursor, p.y()) || !readNumber(cursor, p.z())) {
            file.failAtLine("a vertex (v) needs three numbers" + decimalCommaHint(line) + ".");
        }
        points.push_back(p);
    }
    return points;
}

void writeXyzPoints(const PointList& points, const std::string& path) {
    writeTextFile(path, [&](std::ostream& out) {
        for (const Point& p : points) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    });
}

}  // namespace

bool isPointCloudFileName(const std::string& path) {
    const std::string ext = extensionOf(path);
    return ext == "ply" || ext == "off" || ext == "obj" || ext == "xyz" || ext == "txt" || ext == "pts";
}

PointList readPointCloud(const std::string& path) {
    if (!isPointCloudFileName(path)) {
        throw InvalidInput("Cannot read '" + path + "': unknown extension; use .ply, .off, .obj, .xyz, .txt or .pts.");
    }
    InputFile file(path);
    const std::string ext = extensionOf(path);
    if (ext == "ply") return readPlyPoints(file);
    if (ext == "off") return readOffVertices(file);
    if (ext == "obj") return readObjVertices(file);
    return readXyz(file);
}

void writePointCloud(const PointList& points, const std::string& path) {
    const std::string ext = extensionOf(path);
    if (ext != "ply" && ext != "xyz") {
        throw InvalidInput("Cannot write '" + path + "': point sets are written as .ply or .xyz.");
    }
    writeFileAtomically(path, [&](const std::string& temporary) {
        if (ext == "ply") writeBinaryPly(temporary, points);
        else writeXyzPoints(points, temporary);
    });
}

}  // namespace pcskeleton
