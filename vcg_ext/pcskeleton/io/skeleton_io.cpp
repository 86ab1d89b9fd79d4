#include "pcskeleton/io/skeleton_io.h"

#include "pcskeleton/io/input_file.h"
#include "pcskeleton/io/ply_reader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace pcskeleton {

namespace {

// ASCII PLY in the layout MeshLab reads back with its edges (the radius also in the vertex
// quality, an empty face element), plus a per-edge `inferred` flag. Written here rather
// than by vcglib's exporter, which has no per-edge properties.
void writeSkeletonPly(const SkeletonGraph& skeleton, const std::string& path) {
    writeTextFile(path, [&](std::ostream& out) {
        out << "ply\nformat ascii 1.0\ncomment pcskeleton curve skeleton; edge inferred = 1: a bone the data does not "
               "show\nelement vertex "
            << skeleton.nodeCount()
            << "\nproperty double x\nproperty double y\nproperty double z\nproperty double quality\n"
               "property float radius\nelement face 0\nproperty list uchar int vertex_indices\nelement edge "
            << skeleton.edgeCount() << "\nproperty int vertex1\nproperty int vertex2\nproperty uchar inferred\n"
               "end_header\n";
        for (std::size_t n = 0; n < skeleton.nodeCount(); ++n) {
            const Point& p = skeleton.nodes[n];
            const float radius = float(skeleton.radii.empty() ? 0.0 : skeleton.radii[n]);
            out << p.x() << ' ' << p.y() << ' ' << p.z() << ' ' << double(radius) << ' ' << std::setprecision(9)
                << radius << std::setprecision(17) << '\n';
        }
        const std::vector<char> inferred = inferredFlags(skeleton);
        for (std::size_t e = 0; e < skeleton.edgeCount(); ++e) {
            out << skeleton.edges[e][0] << ' ' << skeleton.edges[e][1] << ' ' << int(inferred[e]) << '\n';
        }
    });
}

// .obj (v/l) and .cg (v/e): a header line, the nodes, then 1-based edges.
void writeSkeletonLines(const SkeletonGraph& skeleton, const std::string& path, const std::string& header,
                        char edgeKeyword) {
    writeTextFile(path, [&](std::ostream& out) {
        out << header << '\n';
        for (const Point& p : skeleton.nodes) out << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
        for (const Edge& e : skeleton.edges) out << edgeKeyword << ' ' << e[0] + 1 << ' ' << e[1] + 1 << '\n';
    });
}

SkeletonGraph readSkeletonPly(InputFile& file) {
    SkeletonGraph skeleton;
    bool sawVertices = false;
    PlyElementReader vertices{"vertex", {"x", "y", "z", "radius", "quality"}, nullptr, nullptr};
    vertices.begin = [&](const PlyElement& element) {
        if (!element.has("x") || !element.has("y") || !element.has("z")) {
            file.fail("the vertex element has no x, y and z properties.");
        }
        sawVertices = true;
        skeleton.nodes.reserve(file.reservable(element.count, 3));
        skeleton.radii.reserve(file.reservable(element.count, 3));
    };
    vertices.record = [&](const double* v) {
        skeleton.nodes.emplace_back(v[0], v[1], v[2]);
        const double radius = std::isnan(v[3]) ? v[4] : v[3];  // MeshLab keeps it in quality too
        skeleton.radii.push_back(std::isfinite(radius) ? radius : 0.0);
    };
    std::uint64_t edgeNumber = 0;
    PlyElementReader edges{"edge", {"vertex1", "vertex2", "inferred"}, nullptr, nullptr};
    edges.begin = [&](const PlyElement& element) {
        if (!element.has("vertex1") || !element.has("vertex2")) {
            file.fail("the edge element has no vertex1 and vertex2 properties.");
        }
        skeleton.edges.reserve(file.reservable(element.count, 2));
    };
    edges.record = [&](const double* ends) {
        const double n = double(skeleton.nodes.size());
        for (int end = 0; end < 2; ++end) {
            if (!(ends[end] >= 0 && ends[end] < n && ends[end] == std::floor(ends[end]))) {
                file.fail("edge " + std::to_string(edgeNumber) + " refers to vertex " + std::to_string(ends[end]) +
                          ", but the file has " + std::to_string(skeleton.nodes.size()) + " vertices (0-based).");
            }
        }
        skeleton.edges.push_back({int(ends[0]), int(ends[1])});
        if (ends[2] == 1) skeleton.inferred.push_back(skeleton.edges.back());  // NaN when the file has none
        ++edgeNumber;
    };
    readPly(file, {vertices, edges});
    if (!sawVertices) file.fail("the file has no vertex element.");
    return skeleton;
}

// A 1-based OBJ index ("12", "12/5", "-1") resolved against the vertices read so far; 0
// when the token is not one.
long readIndex(const std::string& token, long verticesSoFar) {
    char* end = nullptr;
    errno = 0;
    const long index = std::strtol(token.c_str(), &end, 10);
    if (end == token.c_str() || (*end != '\0' && *end != '/') || errno == ERANGE) return 0;
    return index < 0 ? verticesSoFar + 1 + index : index;  // OBJ's relative indices
}

// .obj (v/l) and .cg (v/e) are line formats with 1-based edge lists. A .cg file states its
// counts in its first line ("# D:3 NV:6 NE:5"); they must match what follows.
SkeletonGraph readSkeletonLines(InputFile& file, const std::string& edgeKeyword) {
    SkeletonGraph skeleton;
    std::vector<std::pair<long, long>> ends;  // 1-based, checked once all vertices are known
    std::vector<std::uint64_t> endLines;
    long declaredNodes = -1, declaredEdges = -1;
    std::string line, keyword;
    while (file.readLine(line)) {
        if (file.lineNumber() == 1 && edgeKeyword == "e") {
            std::sscanf(line.c_str(), "# D:%*d NV:%ld NE:%ld", &declaredNodes, &declaredEdges);
        }
        std::istringstream fields(line);
        if (!(fields >> keyword)) continue;
        if (keyword == "v") {
            const char* cursor = line.c_str() + line.find('v') + 1;
            Point p;
            if (!readNumber(cursor, p.x()) || !readNumber(cursor, p.y()) || !readNumber(cursor, p.z())) {
                file.failAtLine("a vertex (v) needs three numbers" + decimalCommaHint(line) + ".");
            }
            double radius = 0.0;
            while (*cursor == ' ' || *cursor == '\t') ++cursor;
            if (*cursor != '\0' && !readNumber(cursor, radius)) {
                file.failAtLine("the value after a vertex's coordinates (its radius) is not a number" +
                                decimalCommaHint(line) + ".");
            }
            if (!std::isfinite(radius)) radius = 0.0;
            skeleton.nodes.push_back(p);
            skeleton.radii.push_back(radius);
        } else if (keyword == edgeKeyword) {
            std::vector<long> ids;
            for (std::string token; fields >> token;) {
                const long index = readIndex(token, long(skeleton.nodes.size()));
                if (index < 1) file.failAtLine("'" + token + "' is not a vertex index (1-based).");
                ids.push_back(index);
            }
            if (ids.size() < 2) file.failAtLine("a line element (" + edgeKeyword + ") needs two vertices.");
            for (std::size_t k = 0; k + 1 < ids.size(); ++k) {
                ends.emplace_back(ids[k], ids[k + 1]);
                endLines.push_back(file.lineNumber());
            }
        }
    }
    const long n = long(skeleton.nodes.size());
    for (std::size_t e = 0; e < ends.size(); ++e) {
        if (ends[e].first > n || ends[e].second > n) {
            file.fail("line " + std::to_string(endLines[e]) + ": an edge refers to vertex " +
                      std::to_string(std::max(ends[e].first, ends[e].second)) + ", but the file has " +
                      std::to_string(n) + " vertices.");
        }
        skeleton.edges.push_back({int(ends[e].first - 1), int(ends[e].second - 1)});
    }
    if (declaredNodes >= 0 && declaredNodes != n) {
        file.fail("the header declares " + std::to_string(declaredNodes) + " vertices (NV) but the file has " +
                  std::to_string(n) + ".");
    }
    if (declaredEdges >= 0 && declaredEdges != long(ends.size())) {
        file.fail("the header declares " + std::to_string(declaredEdges) + " edges (NE) but the file has " +
                  std::to_string(ends.size()) + ".");
    }
    return skeleton;
}

}  // namespace

bool isSkeletonFileName(const std::string& path) {
    const std::string ext = extensionOf(path);
    return ext == "ply" || ext == "obj" || ext == "cg";
}

void writeSkeleton(const SkeletonGraph& skeleton, const std::string& path) {
    const std::string ext = extensionOf(path);
    if (!isSkeletonFileName(path)) {
        throw InvalidInput("Cannot write '" + path + "': skeletons are written as .ply, .obj or .cg.");
    }
    const std::string nodes = std::to_string(skeleton.nodeCount()), edges = std::to_string(skeleton.edgeCount());
    writeFileAtomically(path, [&](const std::string& temporary) {
        if (ext == "ply") {
            writeSkeletonPly(skeleton, temporary);
        } else if (ext == "obj") {
            writeSkeletonLines(skeleton, temporary, "# curve skeleton: " + nodes + " nodes, " + edges + " edges", 'l');
        } else {
            writeSkeletonLines(skeleton, temporary, "# D:3 NV:" + nodes + " NE:" + edges, 'e');
        }
    });
}

SkeletonGraph readSkeleton(const std::string& path) {
    if (!isSkeletonFileName(path)) {
        throw InvalidInput("Cannot read '" + path + "': skeletons are read from .ply, .obj or .cg files.");
    }
    InputFile file(path);
    const std::string ext = extensionOf(path);
    SkeletonGraph skeleton = ext == "ply" ? readSkeletonPly(file) : readSkeletonLines(file, ext == "obj" ? "l" : "e");
    normalizeEdges(skeleton.edges);
    keepInferredWithinEdges(skeleton);
    return skeleton;
}

}  // namespace pcskeleton
